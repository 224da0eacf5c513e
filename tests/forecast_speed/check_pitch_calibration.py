#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The forecast reads a SIL truth's pitch sensor scale and corrects the drag through it (docs/forecast.md, speed term).

An nsb3.mi SIL truth on slocum_comet.toml whose pitch sensor reads (1 + b) x the hull's pitch, b drawn in
[-0.2, 0.2] from a fresh seed (printed; replay with SEED as a 4th argument), its drag drawn +-5 %: the forecast from
its 2nd surfacing with --speed-correction reads the sensor's scale (JSON current.pitch_scale, hull = scale x m_pitch)
within 3 of its sigmas (at least 0.02) of 1 / (1 + b), and the drag it applies is within 15 % of the truth's drawn
drag (uncalibrated, a 15 % pitch bias alone moves it by ~30 %).
Usage: check_pitch_calibration.py GLIDER_FORECAST_BENCH SOURCE_DIR OUT_DIR [SEED]
"""
import json
import os
import random
import re
import subprocess
import sys


def fail(why):
    print("FAIL pitch_calibration: " + why)
    sys.exit(1)


def main():
    if len(sys.argv) not in (4, 5):
        print(__doc__)
        return 2
    bench, source, out = sys.argv[1:4]
    seed = int(sys.argv[4]) if len(sys.argv) == 5 else random.SystemRandom().randrange(1000000)
    print("seed %d" % seed)
    run = subprocess.run([bench, "--mission", os.path.join(source, "boards/missions/comet-nsb3/missions/nsb3.mi"),
                          "--vehicle", os.path.join(source, "boards/vehicles/slocum_comet.toml"), "--seed", str(seed),
                          "--truths", "1", "--surfacings", "3", "--from", "2", "--runs", "4", "--threads", "1",
                          "--truth-pitch-bias", "0.2", "--speed-correction", "--pitch-calibration", "--out", out],
                         capture_output=True, text=True, timeout=55)
    if run.returncode != 0:
        fail("bench exited %d: %s %s" % (run.returncode, run.stdout[-400:], run.stderr[-400:]))
    drawn = re.search(r"drag x([0-9.]+).*pitch sensor x([0-9.]+)", run.stdout)
    if not drawn:
        fail("no truth drag and pitch sensor in: " + run.stdout[:400])
    drag, sensor = float(drawn.group(1)), float(drawn.group(2))
    with open(os.path.join(out, "seed%d" % seed, "from2", "forecast", "forecast.json")) as f:
        c = json.load(f)["current"]
    print("truth: drag x%.3f, pitch sensor x%.3f (hull = %.3f x m_pitch); forecast: scale %.3f +- %.3f over %d samples, "
          "DR speed x%.3f, drag x%.3f over %d dives" %
          (drag, sensor, 1.0 / sensor, c["pitch_scale"], c["pitch_scale_sigma"], c["pitch_samples"],
           c["pitch_dr_speed_factor"], c["speed_drag_factor"], c["speed_dives"]))
    if c["pitch_samples"] < 100:
        fail("fewer than 100 steady-glide samples read")
    if abs(c["pitch_scale"] * sensor - 1.0) > max(3.0 * c["pitch_scale_sigma"], 0.02):
        fail("scale %.3f +- %.3f, the truth's %.3f" % (c["pitch_scale"], c["pitch_scale_sigma"], 1.0 / sensor))
    if c["speed_dives"] < 1:
        fail("no dive measured")
    if abs(c["speed_drag_factor"] / drag - 1.0) > 0.15:
        fail("corrected drag x%.3f, the truth's x%.3f" % (c["speed_drag_factor"], drag))
    print("PASS pitch_calibration")
    return 0


if __name__ == "__main__":
    sys.exit(main())
