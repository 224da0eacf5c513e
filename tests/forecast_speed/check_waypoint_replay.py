#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The replay judges a waypoint reached on the glider's own dead reckoning (docs/forecast.md, speed term).

SIL truth 727325 (nsb3.mi on slocum_comet.toml, --truth-pitch-bias 0.2: drag x0.906, pitch sensor x1.096, its DR
9 % slow) is 600 m from waypoint 0 at surfacing 8 and its DR never reaches it on the dive after. The forecast from
surfacing 9 with the speed correction read the drag right (x0.912) but replayed that dive on a DR counting the true
speed while carrying the glider's belief of the current (which holds the glider's slow DR): it took waypoint 0 as
reached and forecast 2.4 km off. Replayed on the glider's DR (the pitch scale it read), waypoint 0 is still the one
flown to and the forecast lands within 0.5 km. A measured case replayed, not a design seed.
Usage: check_waypoint_replay.py GLIDER_FORECAST_BENCH SOURCE_DIR OUT_DIR
"""
import json
import os
import re
import subprocess
import sys


def fail(why):
    print("FAIL waypoint_replay: " + why)
    sys.exit(1)


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    bench, source, out = sys.argv[1:4]
    seed = 727325
    run = subprocess.run([bench, "--mission", os.path.join(source, "boards/missions/comet-nsb3/missions/nsb3.mi"),
                          "--vehicle", os.path.join(source, "boards/vehicles/slocum_comet.toml"), "--seed", str(seed),
                          "--truths", "1", "--surfacings", "11", "--from", "9", "--runs", "4", "--threads", "1",
                          "--truth-pitch-bias", "0.2", "--pitch-calibration", "--no-depth-rate-calibration", "--out",
                          out],
                         capture_output=True, text=True, timeout=55)
    if run.returncode != 0:
        fail("bench exited %d: %s %s" % (run.returncode, run.stdout[-400:], run.stderr[-400:]))
    errors = [float(m) for m in re.findall(r"^    forecast +([0-9]+) m,", run.stdout, re.M)]
    if not errors:
        fail("no forecast in: " + run.stdout[:400])
    with open(os.path.join(out, "seed%d" % seed, "from9", "forecast", "forecast.json")) as f:
        d = json.load(f)
    flying = [n for n in d["notes"] if n.startswith("flying to waypoint")]
    c = d["current"]
    print("from surfacing 9: %s; pitch scale %.3f, drag x%.3f; forecast %.0f m off" %
          (flying[0] if flying else "no waypoint note", c["pitch_scale"], c["speed_drag_factor"], errors[0]))
    if c["speed_drag_factor"] == 1.0:
        fail("no speed correction applied: the case is not the one measured")
    if not flying or not flying[0].startswith("flying to waypoint 0 "):
        fail("the replay took waypoint 0 as reached; the truth's DR did not reach it")
    if errors[0] > 500.0:
        fail("forecast %.0f m off (more than 500 m)" % errors[0])
    print("PASS waypoint_replay")
    return 0


if __name__ == "__main__":
    sys.exit(main())
