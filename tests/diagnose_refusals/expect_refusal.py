#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Runs a command that must refuse its input: exit code EXACTLY the one
expected (not a crash, not 0) within a time limit, and stderr matching a
pattern. "Refused" is a result only if the program said why.

  expect_refusal.py CODE REGEX -- COMMAND...
"""
import re
import subprocess
import sys


def main(argv):
    split = argv.index("--")
    code, pattern = int(argv[1]), argv[2]
    command = argv[split + 1:]
    run = subprocess.run(command, capture_output=True, text=True, timeout=120)
    said = run.stderr + run.stdout
    print(said)
    if run.returncode != code:
        print(f"FAIL: exit {run.returncode}, expected {code}: {' '.join(command)}")
        return 1
    if not re.search(pattern, said):
        print(f"FAIL: the message does not match /{pattern}/")
        return 1
    if pattern and "cause:" in run.stdout:
        print("FAIL: a refusal must not name a cause")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
