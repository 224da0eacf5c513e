#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every CppUTest group has a CTest entry: none compiled and never run.

Three sources must agree: the TEST_GROUP(...) lines of every tests/**/*.cpp,
the groups each test program reports itself (`PROGRAM -lg`), and the
`PROGRAM ... -sg GROUP` commands CTest has registered (ctest --show-only).
A group written but compiled into no program, or compiled but with no CTest
entry, fails this test, naming the group, its file and what to do.

usage: check_cpputest_groups.py SOURCE_DIR BUILD_DIR
"""
import json
import os
import re
import subprocess
import sys

GROUP_LINE = re.compile(r"^\s*TEST_GROUP(?:_BASE)?\s*\(\s*(\w+)", re.MULTILINE)


def source_groups(source_dir):
    """{group: file} of every TEST_GROUP in tests/."""
    found = {}
    for root, _, files in os.walk(os.path.join(source_dir, "tests")):
        for name in sorted(files):
            if name.endswith(".cpp"):
                path = os.path.join(root, name)
                with open(path, encoding="utf-8") as f:
                    for group in GROUP_LINE.findall(f.read()):
                        found[group] = os.path.relpath(path, source_dir)
    return found


def registered(build_dir):
    """{program path: {group: CTest name}} from the CTest entries that run `-sg GROUP`."""
    shown = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build_dir, capture_output=True, text=True,
                           timeout=120, check=True)
    programs = {}
    for test in json.loads(shown.stdout)["tests"]:
        command = test.get("command") or []
        if "-sg" in command and command.index("-sg") + 1 < len(command):
            group = command[command.index("-sg") + 1]
            programs.setdefault(command[0], {})[group] = test["name"]
    return programs


def main(source_dir, build_dir):
    written = source_groups(source_dir)
    programs = registered(build_dir)
    failures = []
    compiled = set()
    for program, groups in sorted(programs.items()):
        if not os.access(program, os.X_OK):
            failures.append(f"{program} is not built (build every test program first: ./glider build)")
            continue
        listed = subprocess.run([program, "-lg"], capture_output=True, text=True, timeout=60, check=True).stdout.split()
        compiled.update(listed)
        print(f"{os.path.basename(program)}: {len(listed)} groups, {len(groups)} CTest entries")
        for group in listed:
            if group not in groups:
                failures.append(f"{group} ({written.get(group, '?')}) is compiled into {os.path.basename(program)} "
                                f"but has no CTest entry: register the program with glider_add_cpputest_groups")
        for group, test in groups.items():
            if group not in listed:
                failures.append(f"CTest entry {test} runs group {group}, which {os.path.basename(program)} lacks")
    for group, path in sorted(written.items()):
        if group not in compiled:
            failures.append(f"{group} ({path}) is compiled into no registered test program: add {path} to one")
    print(f"{len(written)} groups in tests/, {len(compiled)} in the test programs, "
          f"{sum(len(g) for g in programs.values())} CTest entries")
    for failure in failures:
        print("FAIL:", failure)
    print("FAIL cpputest_groups" if failures else "PASS cpputest_groups")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
