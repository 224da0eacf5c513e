#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Acceptance test of glider-convert: the real-data CSVs in tests/data/real
were decoded from the binary files in tests/data/real/dbd; converting those
binaries with the CSV's columns must give the same header and the same text
in every field of every row.

  check_convert.py CONVERT REF.csv [--deployment-of REF2.csv ...] -- INPUT...

With --deployment-of, INPUT is a whole deployment that contains the segments
of REF.csv (and REF2.csv ...): each of their rows must be in the output,
equal field by field, except that a science column may be filled in the
segment's first row (the previous segment's last sample brackets it, which a
single-segment CSV cannot see).
"""
import os
import subprocess
import sys
import tempfile


def load(path):
    with open(path) as f:
        lines = [line.rstrip("\n") for line in f if not line.startswith("#")]
    return lines[0].split(","), [line.split(",") for line in lines[1:]]


def compare_rows(header, got_rows, want_rows, label, allow_first_row_science):
    problems = []
    got_by_time = {row[0]: row for row in got_rows}
    for i, want in enumerate(want_rows):
        got = got_by_time.get(want[0])
        if got is None:
            problems.append(f"{label}: row {i + 1} (time {want[0]}) missing")
            continue
        for j, name in enumerate(header):
            if got[j] == want[j]:
                continue
            filled_at_start = allow_first_row_science and i == 0 and want[j] == "" and name.startswith("sci_")
            if not filled_at_start:
                problems.append(f"{label}: row {i + 1} column {name}: got '{got[j]}', want '{want[j]}'")
    return problems


def main():
    args = sys.argv[1:]
    split = args.index("--")
    convert, refs, inputs = args[0], [a for a in args[1:split] if a != "--deployment-of"], args[split + 1:]
    deployment = "--deployment-of" in args[1:split]
    header, _ = load(refs[0])
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "out.csv")
        run = subprocess.run([convert, *inputs, "--columns", ",".join(header), "--out", out, "--quiet"],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stderr)
            return 1
        got_header, got_rows = load(out)
    problems = []
    if got_header != header:
        problems.append(f"header: got {got_header}, want {header}")
    total = 0
    for ref in refs:
        ref_header, want_rows = load(ref)
        total += len(want_rows)
        problems += compare_rows(header, got_rows, want_rows, os.path.basename(ref), deployment)
    if not deployment and len(got_rows) != total:
        problems.append(f"rows: got {len(got_rows)}, want {total}")
    for p in problems[:20]:
        print(p)
    print(f"{len(got_rows)} rows x {len(got_header)} columns converted; {total} reference rows; "
          f"{len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
