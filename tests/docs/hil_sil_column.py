#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""docs/hil.md's "SIL vs HIL (measured)" table: its SIL column is
deterministic (glider-sil, WE01, seed 1, the hil cases' missions and faults,
flown as tests/hil/hil_flight.py flies them), so it is produced by this
script and checked in CI (docs.hil_sil_column); the HIL column is measured
by `ctest -L hil -V` (timed runs) and written by hand.

  hil_sil_column.py SOURCE_DIR BUILD_DIR           check the doc's SIL column
  hil_sil_column.py SOURCE_DIR BUILD_DIR --write   rewrite it
"""
import os
import re
import sys
import tempfile

ABORTS = {3: "depth sensor", 4: "attitude sensor", 5: "actuator fault"}


def sil_events(source_dir, build_dir, name):
    sys.path.insert(0, os.path.join(source_dir, "tests", "hil"))
    import hil_flight  # noqa: E402  (the HIL harness's own SIL run and event reader)
    cwd = os.getcwd()
    os.chdir(source_dir)
    try:
        with tempfile.TemporaryDirectory(prefix="hil_sil_") as tmp:
            return hil_flight.events(hil_flight.run_sil(build_dir, source_dir, hil_flight.CASES[name], tmp)[0])
    finally:
        os.chdir(cwd)


def column(source_dir, build_dir):
    """{(case, quantity): SIL cell} for the table's rows."""
    cells = {}
    for name in ("waypoint", "yo"):
        e = sil_events(source_dir, build_dir, name)
        changes = e["phases"][1:]  # after the phase the log starts in
        inflections = [depth for _, phase, depth in changes if phase in (1, 2)][1:] if name == "waypoint" else \
            [depth for _, phase, depth in changes if phase in (1, 2)]
        times = " / ".join("%.0f" % t for t, _, _ in changes)
        depths = ", ".join("%.1f" % d for d in inflections)
        if name == "waypoint":
            cells[(name, "dive / climb / dive / climb / surface at, s")] = times
            cells[(name, "inflection depths, m")] = depths
            cells[(name, "yos, max depth")] = "%d, %.1f m" % (e["yos"], e["max_depth"])
            cells[(name, "waypoint reached at")] = ", ".join("%.0f s" % t for t in e["waypoints"])
            cells[(name, "DR error at the surfacing")] = ", ".join("%.1f m" % err for _, err in e["dr"])
            cells[(name, "mission complete at, s")] = "%.0f" % e["end_t"]
        else:
            cells[(name, "climb / dive / climb / surface at, s")] = times
            cells[(name, "inflection depths, m")] = depths
            cells[(name, "yos, end")] = "%d, %.0f s" % (e["yos"], e["end_t"] + 0.0)
    for name, row in (("pump_stall", "pump_stall @125 s"), ("depth_silent", "depth_silent @60 s"),
                      ("compass_silent", "compass_silent @60 s")):
        e = sil_events(source_dir, build_dir, name)
        cells[(row, "abort")] = "%s at %.0f s" % (ABORTS.get(e["abort"], "cause %d" % e["abort"]), e["abort_t"])
    return cells


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__.strip().splitlines()[-2].strip(), file=sys.stderr)
        return 2
    source_dir, build_dir = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    path = os.path.join(source_dir, "docs", "hil.md")
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    want = column(source_dir, build_dir)
    case, found, wrong = None, set(), []
    for i, line in enumerate(lines):
        cells = line.split(" | ")
        if not line.startswith("| ") or len(cells) != 4:
            continue
        first = cells[0][2:].strip()
        case = first or case
        key = (case, cells[1].strip())
        if key in want:
            found.add(key)
            if cells[2].strip() != want[key]:
                wrong.append("docs/hil.md:%d: %s, %s: SIL %s, the doc says %s" % (i + 1, key[0], key[1], want[key],
                                                                                  cells[2].strip()))
                cells[2] = want[key]
                lines[i] = " | ".join(cells)
    missing = [k for k in want if k not in found]
    if missing:
        print("FAIL hil_sil_column: rows not in docs/hil.md's table: %s" % missing)
        return 1
    if len(argv) == 3 and argv[2] == "--write":
        with open(path, "w", encoding="utf-8") as f:
            f.write("\n".join(lines))
        print("docs/hil.md: %d SIL cells rewritten" % len(wrong))
        return 0
    for line in wrong:
        print(line)
    if wrong:
        print("FAIL hil_sil_column: regenerate with python3 tests/docs/hil_sil_column.py . build/release --write "
              "(and measure the HIL column with ctest -L hil -V)")
        return 1
    print("%d SIL cells as glider-sil flies them\nPASS hil_sil_column" % len(want))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
