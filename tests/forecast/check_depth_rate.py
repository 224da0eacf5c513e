#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The depth-rate calibration reads what slows or speeds a glider (docs/forecast.md, "The depth-rate calibration").

Two SIL truths on a fresh seed (printed; replay with --seed):
- box.mi (pitch servo) whose pitch sensor reads (1 + b) x the hull's, b drawn in [-0.2, 0.2], the servo holding the
  sensor at the mission's pitch (--truth-servo-on-sensor: the hull flies the mission's / (1 + b), as comet-2016's),
  its drag the file's (under a servo a drag off the file's reads as the sensor's scale: the depth rates cannot tell
  them apart): the forecast reads hull = scale x m_pitch with scale within 1 % of 1 / (1 + b), and the truth's drawn
  buoyancy within 2 g (measured on 5 fresh seeds: 0.2 %, 0.6 g);
- nsb3.mi (battery fixed) on slocum_comet.toml with the drag x1.25 (times the drawn 5 %), read and said but not
  flown by default, the same reading flown with --depth-rate-drag: the drag within 1.5 % of
  the truth's, the buoyancy within 2 g (measured: 0.1 %, 0.6 g).
Usage: check_depth_rate.py GLIDER_FORECAST_BENCH SOURCE_DIR OUT_DIR [--seed N]
"""
import json
import os
import random
import re
import subprocess
import sys


def fail(why):
    print("FAIL depth_rate: " + why)
    sys.exit(1)


def truth_and_calibration(bench, source, out, seed, mission, extra, applied=True):
    run = subprocess.run([bench, "--mission", os.path.join(source, mission), "--vehicle",
                          os.path.join(source, "boards/vehicles/slocum_comet.toml"), "--seed", str(seed), "--truths",
                          "1", "--surfacings", "3", "--from", "2", "--runs", "4", "--threads", "1", "--out", out] +
                         extra, capture_output=True, text=True, timeout=50)
    if run.returncode != 0:
        fail("bench exited %d: %s %s" % (run.returncode, run.stdout[-400:], run.stderr[-400:]))
    m = re.search(r"drag x([0-9.]+), buoyancy ([-+0-9]+) g, pitch sensor x([0-9.]+)", run.stdout)
    if not m:
        fail("no truth in: " + run.stdout[:400])
    with open(os.path.join(out, "seed%d" % seed, "from2", "forecast", "forecast.json")) as f:
        d = json.load(f)["depth_rate"]
    if not d["read"] or d["applied"] != applied:
        fail("%s: the depth rates not read, or applied %s where %s was due: %s" % (mission, d["applied"], applied, d))
    return float(m.group(1)), float(m.group(2)), float(m.group(3)), d


def main():
    args = sys.argv[1:]
    seed = random.SystemRandom().randrange(1000000)
    if "--seed" in args:
        i = args.index("--seed")
        seed = int(args[i + 1])
        del args[i:i + 2]
    if len(args) != 3:
        print(__doc__)
        return 2
    bench, source, out = args
    print("seed %d (replay: --seed %d)" % (seed, seed))
    drag, buoyancy, sensor, d = truth_and_calibration(
        bench, source, os.path.join(out, "servo"), seed, "boards/missions/box_current/missions/box.mi",
        ["--truth-pitch-bias", "0.2", "--truth-servo-on-sensor", "--truth-drag-sigma", "0"])
    print("servo: truth sensor x%.3f (hull x%.3f of m_pitch), buoyancy %+.0f g; read hull x%.3f, buoyancy %+.1f g" %
          (sensor, 1.0 / sensor, buoyancy, d["pitch_scale"], d["buoyancy_g"]))
    if not d["servo"]:
        fail("box.mi's servo not seen")
    if abs(d["pitch_scale"] * sensor - 1.0) > 0.01:
        fail("pitch scale x%.3f, the truth's x%.3f" % (d["pitch_scale"], 1.0 / sensor))
    # The truth's buoyancy is printed rounded to 1 g.
    if abs(d["buoyancy_g"] - buoyancy) > 2.0:
        fail("buoyancy %+.1f g, the truth's %+.0f g" % (d["buoyancy_g"], buoyancy))
    # With the battery fixed the calibration is read and said, flown only with --depth-rate-drag.
    _, _, _, said = truth_and_calibration(
        bench, source, os.path.join(out, "fixed_said"), seed, "boards/missions/comet-nsb3/missions/nsb3.mi",
        ["--truth-drag", "1.25"], applied=False)
    drag, buoyancy, _, d = truth_and_calibration(
        bench, source, os.path.join(out, "fixed"), seed, "boards/missions/comet-nsb3/missions/nsb3.mi",
        ["--truth-drag", "1.25", "--depth-rate-drag"])
    if said["drag_factor"] != d["drag_factor"] or said["buoyancy_g"] != d["buoyancy_g"]:
        fail("the calibration read differently when flown: %s against %s" % (said, d))
    print("battery fixed: truth drag x%.3f, buoyancy %+.0f g; read drag x%.3f, buoyancy %+.1f g" %
          (drag, buoyancy, d["drag_factor"], d["buoyancy_g"]))
    if d["servo"]:
        fail("nsb3.mi's fixed battery read as a servo")
    if abs(d["drag_factor"] / drag - 1.0) > 0.015:
        fail("drag x%.3f, the truth's x%.3f" % (d["drag_factor"], drag))
    if abs(d["buoyancy_g"] - buoyancy) > 2.0:
        fail("buoyancy %+.1f g, the truth's %+.0f g" % (d["buoyancy_g"], buoyancy))
    print("PASS depth_rate")
    return 0


if __name__ == "__main__":
    sys.exit(main())
