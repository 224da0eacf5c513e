#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every shipped vehicle (boards/vehicles/*.toml) through the demo mission at
the default integration step (issue 28: the IIT Madras lab glider went NaN
~40 s in and was reported as a depth-sensor abort with "nan km"). Each vehicle
either flies it to the end (mission complete, no abort, no NaN in the log's
model columns, finite distance) or the mission is refused up front (exit 1,
"mission refused": its ballast limits do not fit that vehicle).

  fly_every_vehicle.py GLIDER_SIL SOURCE_DIR WORK_DIR
"""
import csv
import glob
import math
import os
import subprocess
import sys


def fail(message):
    print("FAIL vehicle_stability: " + message)
    sys.exit(1)


def main():
    sil, source, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    mission = os.path.join(source, "boards", "missions", "demo_yo.toml")
    vehicles = sorted(glob.glob(os.path.join(source, "boards", "vehicles", "*.toml")))
    if not vehicles:
        fail("no vehicles in boards/vehicles")
    flown = 0
    for vehicle in vehicles:
        name = os.path.basename(vehicle)[:-5]
        log = os.path.join(work, name + ".csv")
        run = subprocess.run([sil, "--vehicle", vehicle, "--mission", mission, "--out", log, "--quiet"],
                             capture_output=True, text=True, timeout=50)
        said = (run.stdout + run.stderr).strip()
        if run.returncode == 1 and "mission refused" in said:
            print("%s: refused: %s" % (name, said.splitlines()[-1]))
            continue
        if run.returncode != 0:
            fail("%s: exit %d: %s" % (name, run.returncode, said[-400:]))
        with open(log) as f:
            lines = [line for line in f if not line.startswith("#")]
        rows = list(csv.DictReader(lines))
        for i, row in enumerate(rows):
            for column, value in row.items():
                try:
                    finite = not value or math.isfinite(float(value))
                except ValueError:
                    finite = True  # a text column
                if not finite:
                    fail("%s: %s data row %d: %s = %s" % (name, log, i + 1, column, value))
        with open(log) as f:
            text = f.read()
        end = text.rstrip().splitlines()[-1]
        if not end.startswith("# end: complete"):
            fail("%s: the flight did not complete: %s" % (name, end))
        print("%s: %d rows, %s" % (name, len(rows), end))
        flown += 1
    if flown == 0:
        fail("the demo mission flew no shipped vehicle")
    print("PASS vehicle_stability (%d of %d vehicles flown, the rest refused)" % (flown, len(vehicles)))


if __name__ == "__main__":
    main()
