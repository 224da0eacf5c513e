#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Instructions per simulated second of glider-sil, split into the model, the
firmware, the SIL's simulated devices and the CSV log (docs/sil.md, Speed).

Counted with callgrind (no hardware counters on the build machines, and an
instruction count does not depend on the machine's load): every function's
own instructions go to a part by its name (glider::model, odeint and Eigen:
model; glider::fw and glider::hal: firmware; the CSV writer and the log text:
log; the rest of glider::sil: SIL devices and loop), and the instructions of
the library calls a function makes (libm, libstdc++'s to_chars, libc's
write) go to the caller's part. The mission is flown twice, to two simulated
times, and the difference is divided by the difference of the times: start-up
(reading the vehicle and mission files) cancels out.

    sil_instructions.py --sil NEW [--baseline OLD] [--variant 'LABEL=OPTIONS']... --mission M --vehicle V
"""

import argparse
import os
import re
import shlex
import subprocess
import sys
import tempfile

PARTS = ("model", "firmware", "sil", "log", "other")
RULES = (  # first match wins
    ("log", re.compile(r"CsvFlightLog|LogRowFormatter|BinaryRowEncoder|glider::fw::comms::crc32_update|glider::fw::format_log|glider::fw::\(anonymous namespace\)::put"
                       r"|glider::fw::\(anonymous namespace\)::format_fields|glider::sil::SimCtd")),
    ("model", re.compile(r"glider::model::|boost::numeric::odeint|Eigen::")),
    ("firmware", re.compile(r"glider::fw::|glider::hal::")),
    ("sil", re.compile(r"glider::sil::")),
)


def part_of(function):
    for part, pattern in RULES:
        if pattern.search(function):
            return part
    return "other"


def read_callgrind(path):
    """(self costs {(object, function): Ir}, call edges [(caller, callee, inclusive Ir)], total Ir)."""
    names = {"fn": {}, "ob": {}}
    self_costs = {}
    edges = []
    total = None
    current_object = ""
    caller = None
    callee = None
    callee_object = None  # cob= of the pending call, if given
    after_calls = False

    def resolve(kind, text):
        match = re.match(r"\((\d+)\)(?: (.*))?", text)
        if not match:
            return text
        if match.group(2) is not None:
            names[kind][match.group(1)] = match.group(2)
        return names[kind].get(match.group(1), "")

    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            if not line or line[0] == "#":
                continue
            if line.startswith("totals:") or line.startswith("summary:"):
                total = int(line.split()[1])
            elif line.startswith("ob="):
                current_object = resolve("ob", line[3:])
            elif line.startswith("fn="):
                caller = (current_object, resolve("fn", line[3:]))
            elif line.startswith("cob="):
                callee_object = resolve("ob", line[4:])
            elif line.startswith("cfn="):
                callee = resolve("fn", line[4:])
            elif line.startswith("calls="):
                after_calls = True
            elif line[0].isdigit() or line[0] in "+-*":
                fields = line.split()
                cost = int(fields[1]) if len(fields) > 1 else 0
                if after_calls:
                    target = (callee_object if callee_object is not None else current_object, callee)
                    edges.append((caller, target, cost))
                    after_calls = False
                    callee_object = None
                else:
                    self_costs[caller] = self_costs.get(caller, 0) + cost
    return self_costs, edges, total


def split_costs(path, program):
    """{part: instructions} from a callgrind output file of `program`, and the
    instructions left unattributed (start-up code that libc calls back)."""
    self_costs, edges, total = read_callgrind(path)

    def ours(function):
        return os.path.realpath(function[0]) == program

    # Library functions that call back into the program, directly or through
    # other library functions (libc's start calling main): the inclusive cost
    # of a call into them holds the program's own instructions, counted
    # already. Every other library call is a leaf for the program (libm,
    # to_chars, memcpy, write) and is charged to its caller.
    calls_back = set()
    changed = True
    while changed:
        changed = False
        for caller, callee, _ in edges:
            if not ours(caller) and caller not in calls_back and (ours(callee) or callee in calls_back):
                calls_back.add(caller)
                changed = True
    totals = dict.fromkeys(PARTS, 0)
    for function, cost in self_costs.items():
        if ours(function):
            totals[part_of(function[1])] += cost
    for caller, callee, cost in edges:
        if ours(caller) and not ours(callee) and callee not in calls_back:
            totals[part_of(caller[1])] += cost
    unattributed = (total or 0) - sum(totals.values())
    return totals, unattributed


def fly(sil, sil_args, mission, vehicle, sim_time_s, workdir, tag):
    out = os.path.join(workdir, f"{tag}_{int(sim_time_s)}.callgrind")
    log = os.path.join(workdir, f"{tag}.csv")
    options = [option.replace("{dir}", workdir) for option in sil_args]
    if "--out" not in options:
        options += ["--out", log]
    command = ["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}", sil, "--mission", mission,
               "--vehicle", vehicle, "--quiet", "--max-sim-time-s", str(sim_time_s)] + options
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode not in (0, 3):  # 3: stopped by the time limit, as asked
        sys.exit(f"sil_instructions: {' '.join(command)} failed ({run.returncode}):\n{run.stderr}")
    totals, unattributed = split_costs(out, os.path.realpath(sil))
    totals["other"] += unattributed  # the dynamic loader and libc's start: cancels in per_sim_second
    return totals


def per_sim_second(sil, sil_args, mission, vehicle, times, workdir, tag):
    short = fly(sil, sil_args, mission, vehicle, times[0], workdir, tag)
    long = fly(sil, sil_args, mission, vehicle, times[1], workdir, tag)
    return {part: (long[part] - short[part]) / (times[1] - times[0]) for part in PARTS}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sil", required=True, help="glider-sil to measure")
    parser.add_argument("--baseline", help="another glider-sil (today's): the ratios are printed against it")
    parser.add_argument("--variant", action="append", default=[],
                        help="LABEL=OPTIONS: also measure --sil with these glider-sil options (repeatable; "
                        "'{dir}' is a temporary directory; default --out: a CSV log there)")
    parser.add_argument("--mission", required=True)
    parser.add_argument("--vehicle", required=True)
    parser.add_argument("--times", default="1800,9000", help="the two simulated times, s")
    args = parser.parse_args()
    times = [float(t) for t in args.times.split(",")]
    configs = [("baseline", args.baseline, [])] if args.baseline else []
    configs.append(("this build", args.sil, []))
    for variant in args.variant:
        label, _, options = variant.partition("=")
        configs.append((label, args.sil, shlex.split(options)))
    runs = []
    with tempfile.TemporaryDirectory(prefix="sil_instructions_") as workdir:
        for index, (label, sil, options) in enumerate(configs):
            costs = per_sim_second(sil, options, args.mission, args.vehicle, times, workdir, f"run{index}")
            runs.append((label, costs))
    print(f"  instructions per simulated second (callgrind; {os.path.basename(args.mission)} from "
          f"{times[0]:.0f} to {times[1]:.0f} s; CSV log written unless said):")
    print("    %-14s %9s %9s %9s %9s %9s %9s" % ("", *PARTS, "total"))
    for label, costs in runs:
        ratio = ""
        if args.baseline and label != "baseline":
            base = runs[0][1]
            ratio = "  baseline/this: total %.1fx (%s)" % (
                sum(base.values()) / sum(costs.values()),
                ", ".join(f"{p} {base[p] / costs[p]:.1f}x" for p in ("model", "firmware", "log") if costs[p] > 0))
        print("    %-14s %9.0f %9.0f %9.0f %9.0f %9.0f %9.0f%s" % (label, *(costs[p] for p in PARTS),
                                                                  sum(costs.values()), ratio))


if __name__ == "__main__":
    main()
