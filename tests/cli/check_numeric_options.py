#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every number option of every program refuses bad values.

The table is the programs' own: each prints its number options and their
ranges with the hidden --list-numeric-options (glider::cli::Tool), so a new
option is tried the day it is declared. Each option is given NaN, +-inf,
+-1e308 and values just outside its range (and a fraction for an integer);
each must be a usage error (exit 2) within a few seconds whose message names
the option, the value as typed and the allowed range. A number option
declared without a range (plain CLI11 add_option) fails the test, and so does
a program of the source tree that is not on the command line.

Usage: check_numeric_options.py SOURCE_DIR [--absent NAME]... PROGRAM...
(--absent: a program of the source tree this build does not make.)
"""

import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time

TIMEOUT_S = 10.0  # one refusal; the parse error comes before anything runs


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def programs_in_source(source_dir):
    """Names of every glider::cli::Tool in the source tree's mains."""
    names = set()
    pattern = re.compile(r'glider::cli::Tool\s+tool\(\s*"([^"]+)"|cli::Tool\s+tool\(\s*"([^"]+)"')
    for top in ("firmware", "sil", "tools", "benchmarks"):
        for root, _, files in os.walk(os.path.join(source_dir, top)):
            for name in files:
                if name.endswith(".cpp"):
                    with open(os.path.join(root, name), encoding="utf-8") as f:
                        for match in pattern.finditer(f.read()):
                            names.add(match.group(1) or match.group(2))
    return names


def bad_values(option):
    """The values to try: text as typed on the command line."""
    values = ["nan", "inf", "-inf", "1e308", "-1e308"]
    if option["integer"]:
        low, high = option["min"], option["max"]
        values += [str(low - 1), str(high + 1), f"{low}.5"]
    else:
        low, high = option["min"], option["max"]
        values += [repr(low - max(abs(low) * 1e-6, 1e-9)), repr(high + max(abs(high) * 1e-6, 1e-9))]
    return values


def command_line(program, option, value):
    args = [program]
    if option["command"]:
        args.append(option["command"])
    args += option["leading"]
    if option["positional"]:
        args += ["--", value]
    else:
        args.append(f"{option['name']}={value}")
    return args


def try_value(program, option, value):
    """'' when refused as it should be, else what went wrong."""
    args = command_line(program, option, value)
    start = time.monotonic()
    try:
        run = subprocess.run(args, capture_output=True, text=True, timeout=TIMEOUT_S, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return f"{' '.join(args)}: still running after {TIMEOUT_S:.0f} s"
    elapsed = time.monotonic() - start
    text = run.stdout + run.stderr
    where = f"{' '.join(args)} (exit {run.returncode}, {elapsed:.1f} s)"
    if run.returncode != 2:
        return f"{where}: expected exit 2 (usage); said: {text.strip()[:300]}"
    for part in (option["name"], value, option["allowed"]):
        if part not in text:
            return f"{where}: the message does not name '{part}': {text.strip()[:300]}"
    return ""


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    source_dir, args = sys.argv[1], sys.argv[2:]
    absent = set()
    while args and args[0] == "--absent":
        absent.add(args[1])
        args = args[2:]
    programs = args
    tables = []
    for program in programs:
        run = subprocess.run([program, "--list-numeric-options"], capture_output=True, text=True, timeout=TIMEOUT_S)
        if run.returncode != 0:
            fail(f"{program} --list-numeric-options: exit {run.returncode}: {run.stderr.strip()}")
        table = json.loads(run.stdout)
        if table["unregistered"]:
            fail(f"{table['program']}: number options without a range (declare them with Tool::add_number or "
                 f"add_integer): {table['unregistered']}")
        tables.append((program, table))
    listed = {table["program"] for _, table in tables}
    missing = programs_in_source(source_dir) - listed - absent
    if missing:
        fail(f"programs of the source tree not tried (add them to tests/cli/CMakeLists.txt): {sorted(missing)}")

    cases = [(program, option, value) for program, table in tables for option in table["options"]
             for value in bad_values(option)]
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        problems = [p for p in pool.map(lambda c: try_value(*c), cases) if p]
    options = sum(len(table["options"]) for _, table in tables)
    print(f"{len(tables)} programs, {options} number options, {len(cases)} bad values tried "
          f"in {time.monotonic() - start:.1f} s")
    for program, table in tables:
        names = ", ".join((o["command"] + " " if o["command"] else "") + o["name"] + " " + o["allowed"]
                          for o in table["options"])
        print(f"  {table['program']}: {names or '(no number options)'}")
    if problems:
        for problem in problems[:20]:
            print("FAIL: " + problem)
        fail(f"{len(problems)} of {len(cases)} bad values not refused as a usage error naming option, value and range")
    print("PASS every number option refuses NaN, inf, 1e308 and out-of-range values")
    return 0


if __name__ == "__main__":
    sys.exit(main())
