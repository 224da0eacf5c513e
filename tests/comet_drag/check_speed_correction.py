#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The forecast's speed correction finds a truth's drag (docs/forecast.md, speed term).

An nsb3.mi SIL truth on slocum_comet.toml with its drag x1.4 (--truth-drag 1.4,
times the drawn 5 %), forecast from its 3rd surfacing with --speed-correction:
the JSON's current.speed_drag_factor is within 15 % of the truth's drawn drag
(the DR speed's own spread over 3 dives), and with --no-speed-correction it is 1.
Usage: check_speed_correction.py GLIDER_FORECAST_BENCH OUT_DIR
"""
import json
import os
import re
import subprocess
import sys


def fail(why):
    print("FAIL speed_correction: " + why)
    sys.exit(1)


def forecast(bench, source, out, extra):
    run = subprocess.run([bench, "--mission", os.path.join(source, "boards/missions/comet-nsb3/missions/nsb3.mi"),
                          "--vehicle", os.path.join(source, "boards/vehicles/slocum_comet.toml"), "--seed", "5",
                          "--truths", "1", "--surfacings", "5", "--from", "3", "--runs", "8", "--threads", "1",
                          "--truth-drag", "1.4", "--no-depth-rate-calibration", "--out", out] + extra, capture_output=True, text=True, timeout=50)
    if run.returncode != 0:
        fail("bench exited %d: %s %s" % (run.returncode, run.stdout[-400:], run.stderr[-400:]))
    drawn = re.search(r"drag x([0-9.]+)", run.stdout)
    if not drawn:
        fail("no truth drag in: " + run.stdout[:400])
    with open(os.path.join(out, "seed5", "from3", "forecast", "forecast.json")) as f:
        return float(drawn.group(1)), json.load(f)["current"]


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    bench, source, out = sys.argv[1:]
    truth, on = forecast(bench, source, os.path.join(out, "on"), ["--speed-correction"])
    _, off = forecast(bench, source, os.path.join(out, "off"), ["--no-speed-correction"])
    print("truth drag x%.3f; corrected x%.3f over %d dives (ratio before %.3f); without the option x%.3f" %
          (truth, on["speed_drag_factor"], on["speed_dives"], on["glider_speed_ratio"], off["speed_drag_factor"]))
    if on["speed_dives"] < 2:
        fail("fewer than 2 dives measured")
    if abs(on["speed_drag_factor"] / truth - 1.0) > 0.15:
        fail("corrected drag x%.3f, the truth's x%.3f" % (on["speed_drag_factor"], truth))
    if off["speed_drag_factor"] != 1.0:
        fail("a drag factor applied with --no-speed-correction")
    print("PASS speed_correction")
    return 0


if __name__ == "__main__":
    sys.exit(main())
