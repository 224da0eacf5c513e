#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-diagnose takes a glider's binary files directly: the diagnosis of
the binaries equals the one of the CSV made from them (same samples, same
named cause; RMS figures equal to the CSV's 7-digit rounding).

  check_diagnose_binary.py DIAGNOSE VEHICLE CSV -- BINARY...
"""
import json
import subprocess
import sys


def diagnose(tool, vehicle, inputs):
    run = subprocess.run([tool, *inputs, "--vehicle", vehicle, "--model", "steady", "--json"],
                         capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{' '.join(inputs)}: exit {run.returncode}\n{run.stdout}\n{run.stderr}")
    return json.loads(run.stdout)


def main():
    args = sys.argv[1:]
    split = args.index("--")
    tool, vehicle, csv = args[:split]
    binary = diagnose(tool, vehicle, args[split + 1:])
    text = diagnose(tool, vehicle, [csv])
    problems = []
    for key in ("samples_used", "train_samples", "heldout_samples"):
        if binary[key] != text[key]:
            problems.append(f"{key}: binary {binary[key]}, csv {text[key]}")
    if binary.get("cause") != text.get("cause"):
        problems.append(f"cause: binary {binary.get('cause')}, csv {text.get('cause')}")
    a = binary["baseline"]["rms_depth_rate_m_s"]
    b = text["baseline"]["rms_depth_rate_m_s"]
    if abs(a - b) > 1e-5 * abs(b):
        problems.append(f"baseline rms depth rate: binary {a}, csv {b}")
    print("\n".join(problems) or f"same diagnosis: {binary['samples_used']} samples, baseline rms {a:.6f} m/s")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
