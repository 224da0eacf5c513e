#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The comet glider has no drag cliff (issue 24, docs/forecast.md "speed term").

boards/vehicles/slocum_comet.toml with its drag (cd0 and cd_alpha2, as the
forecast's and the SIL truths' drag draws scale it) x1.0 ... x1.5:
- steady (glider-steady, the mission's pump-only dive: -230 cc, m_battpos
  0.405 in): a glide exists at every factor, at |a| < 8 deg;
- flown (glider-sil, boards/missions/comet-nsb3/missions/nsb3.mi, 3 h): the
  median |angle of attack| below 5 m is < 8 deg, and the median horizontal
  speed falls with every 10 % of drag by at most 10 % (drag^-1/2 is 4.7 %;
  the old file's WE01 polar fell 58 % from x1.0 to x1.1, onto a stalled
  branch at a ~ 17 deg).
Usage: check_comet_drag.py GLIDER_SIL GLIDER_STEADY SOURCE_DIR OUT_DIR
"""
import csv
import json
import math
import os
import re
import statistics
import subprocess
import sys

FACTORS = [1.0, 1.1, 1.2, 1.3, 1.4, 1.5]
MAX_ALPHA_DEG = 8.0
MAX_STEP_DROP = 0.10


def fail(why):
    print("FAIL comet_drag: " + why)
    sys.exit(1)


def scaled(text, factor):
    out = text
    for key in ("cd0", "cd_alpha2"):
        pattern = re.compile(r"^%s = ([0-9.eE+-]+)" % key, re.M)
        if not pattern.search(out):
            fail("no %s in the vehicle file" % key)
        out = pattern.sub(lambda m: "%s = %.10g" % (key, float(m.group(1)) * factor), out, count=1)
    return out


def flown(sil, mission, vehicle, log):
    run = subprocess.run([sil, "--mission", mission, "--vehicle", vehicle, "--max-sim-time-s", "10800", "--quiet",
                          "--out", log], capture_output=True, text=True, timeout=50)
    # 3: stopped by the time limit (README, exit codes), as asked.
    if run.returncode not in (0, 3) or not os.path.exists(log):
        fail("glider-sil on %s exited %d: %s" % (vehicle, run.returncode, run.stderr.strip()))
    alpha, speed = [], []
    with open(log) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            if float(row["sim_depth_m"]) > 5.0:
                alpha.append(abs(float(row["sim_alpha_rad"])))
                speed.append(float(row["sim_horizontal_speed_m_s"]))
    if len(alpha) < 1000:
        fail("%s: only %d rows below 5 m" % (vehicle, len(alpha)))
    return math.degrees(statistics.median(alpha)), statistics.median(speed)


def steady(tool, vehicle):
    run = subprocess.run([tool, "--vehicle", vehicle, "--ballast-cc", "-230", "--battpos-in", "0.405", "--depth-m",
                          "20", "--json"], capture_output=True, text=True, timeout=30)
    result = json.loads(run.stdout)
    return result.get("angle_of_attack_deg"), result.get("error")


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        return 2
    sil, steady_tool, source, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    mission = os.path.join(source, "boards/missions/comet-nsb3/missions/nsb3.mi")
    with open(os.path.join(source, "boards/vehicles/slocum_comet.toml")) as f:
        text = f.read()
    previous = None
    for factor in FACTORS:
        vehicle = os.path.join(out, "comet_drag_x%.1f.toml" % factor)
        with open(vehicle, "w") as f:
            f.write(scaled(text, factor))
        steady_alpha, error = steady(steady_tool, vehicle)
        if steady_alpha is None:
            fail("drag x%.1f: no steady pump-only dive (%s)" % (factor, error))
        alpha, speed = flown(sil, mission, vehicle, os.path.join(out, "comet_drag_x%.1f.csv" % factor))
        print("drag x%.1f: steady a %.2f deg; flown median |a| %.2f deg, horizontal %.3f m/s" %
              (factor, steady_alpha, alpha, speed))
        if abs(steady_alpha) >= MAX_ALPHA_DEG:
            fail("drag x%.1f: steady a %.2f deg" % (factor, steady_alpha))
        if alpha >= MAX_ALPHA_DEG:
            fail("drag x%.1f: flown median |a| %.2f deg (stalled)" % (factor, alpha))
        if previous is not None and not (previous * (1.0 - MAX_STEP_DROP) <= speed < previous):
            fail("drag x%.1f: horizontal speed %.3f after %.3f m/s (not a smooth fall)" % (factor, speed, previous))
        previous = speed
    print("PASS comet_drag: x%.1f-x%.1f glide at small angles of attack, speed falling smoothly" %
          (FACTORS[0], FACTORS[-1]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
