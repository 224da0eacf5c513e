#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The probe's findings that hung or lied, run as a user would run them.

- a FIFO given as the mission blocked glider-sil and glider-firmware
  --check-mission forever: now refused at once (not a regular file);
- glider-actuator-sim --tcp no-such-host:P bound 255.255.255.255 and said it
  served: now a usage error naming the host.

Usage: check_probes.py SOURCE_DIR BUILD_DIR
"""

import os
import subprocess
import sys
import tempfile

TIMEOUT_S = 20.0


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def expect(args, code, text):
    try:
        run = subprocess.run(args, capture_output=True, text=True, timeout=TIMEOUT_S, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        fail(f"{' '.join(args)}: still running after {TIMEOUT_S:.0f} s (hangs)")
    said = (run.stdout + run.stderr).strip()
    if run.returncode != code or text not in said:
        fail(f"{' '.join(args)}: exit {run.returncode} (expected {code}), said: {said[:400]} "
             f"(expected '{text}')")
    print(f"ok: {' '.join(os.path.basename(a) for a in args)} -> exit {code}: {said.splitlines()[-1][:160]}")


def main():
    source, build = sys.argv[1], sys.argv[2]
    sil = os.path.join(build, "sil", "glider-sil")
    firmware = os.path.join(build, "firmware", "linux", "glider-firmware")
    actuator_sim = os.path.join(build, "tools", "hardware", "actuator_sim", "glider-actuator-sim")
    board = os.path.join(source, "boards", "target", "cm4_glider.toml")
    with tempfile.TemporaryDirectory() as tmp:
        for name in ("mission.mi", "mission.toml"):
            fifo = os.path.join(tmp, name)
            os.mkfifo(fifo)
            expect([sil, "--mission", fifo], 1, "not a regular file")
            expect([firmware, "--check-mission", "--board", board, "--mission", fifo], 1, "not a regular file")
    expect([actuator_sim, "--tcp", "no-such-host:1502"], 2, "is not a numeric IPv4 address")
    print("PASS probes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
