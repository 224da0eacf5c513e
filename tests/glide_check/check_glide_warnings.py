#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil says when a flight is not one the vehicle can make (docs/sil-summary.md
`glide_warnings`), and its compass reports Euler angles however the model turns
(hal/include/glider/hal/attitude_sensor.hpp).

- WE01's polar (slocum_we01.toml) flying the comet's nsb3.mi, whose fixed battery
  position climbs it at ~5 deg pitch: shallower than any steady glide of that
  polar, so the model settles on a stalled branch. The run warns on stderr (with
  --quiet too) and lists one warning for the climbs in the summary JSON.
- The comet's own file on the same mission, and WE01 on its demo mission: no warning.
- The IIT Madras lab glider (paper 002) on the demo mission somersaults: its log's
  m_pitch stays within +-90 deg, m_roll within +-180, m_heading in [0, 360)
  (before, m_pitch ran to -204 rad), and the run warns.
Usage: check_glide_warnings.py GLIDER_SIL SOURCE_DIR OUT_DIR
"""
import csv
import json
import math
import os
import subprocess
import sys


def fail(why):
    print("FAIL glide_warnings: " + why)
    sys.exit(1)


def fly(sil, source, out, vehicle, mission, hours, log=None):
    name = "%s_%s" % (vehicle, os.path.basename(mission).split(".")[0])
    summary = os.path.join(out, name + ".json")
    command = [sil, "--mission", os.path.join(source, mission), "--vehicle",
               os.path.join(source, "boards/vehicles", vehicle + ".toml"), "--max-sim-time-s", str(hours * 3600),
               "--quiet", "--summary-json", summary]
    if log:
        command += ["--out", log]
    run = subprocess.run(command, capture_output=True, text=True, timeout=50)
    if run.returncode not in (0, 3):  # 3: aborted or stopped by the time limit (README, exit codes)
        fail("%s on %s exited %d: %s" % (vehicle, mission, run.returncode, run.stderr.strip()[-300:]))
    with open(summary) as f:
        warnings = json.load(f)["glide_warnings"]
    printed = [line for line in run.stderr.splitlines() if line.startswith("glider-sil: warning: ")]
    if len(printed) != len(warnings):
        fail("%s on %s: %d warnings printed, %d in the summary" % (vehicle, mission, len(printed), len(warnings)))
    print("%s on %s: %d glide warning(s) %s" % (vehicle, mission, len(warnings), warnings))
    return warnings


def main():
    if len(sys.argv) != 4:
        print(__doc__)
        return 2
    sil, source, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    nsb3 = "boards/missions/comet-nsb3/missions/nsb3.mi"
    stalled = fly(sil, source, out, "slocum_we01", nsb3, 3)
    if len(stalled) != 1 or not stalled[0].startswith("climbs:") or "no steady glide" not in stalled[0]:
        fail("WE01 on nsb3.mi: expected one warning for the climbs, got %s" % stalled)
    for vehicle, mission in (("slocum_comet", nsb3), ("slocum_we01", "boards/missions/demo_yo.toml")):
        if fly(sil, source, out, vehicle, mission, 3):
            fail("%s on %s is a flyable mission, warned" % (vehicle, mission))
    log = os.path.join(out, "iitm_demo.csv")
    if not fly(sil, source, out, "iitm_lab_glider", "boards/missions/demo_yo.toml", 1, log):
        fail("the somersaulting lab glider was not warned about")
    rows = 0
    with open(log) as f:
        for row in csv.DictReader(line for line in f if not line.startswith("#")):
            pitch, roll, heading = (float(row[k]) for k in ("m_pitch", "m_roll", "m_heading"))
            rows += 1
            if math.isnan(pitch):
                continue
            if abs(pitch) > math.pi / 2 or abs(roll) > math.pi or not 0.0 <= heading < 2 * math.pi:
                fail("%s row %d: m_pitch %g, m_roll %g, m_heading %g rad outside the Euler ranges" %
                     (log, rows, pitch, roll, heading))
    if rows < 500:
        fail("%s: only %d rows" % (log, rows))
    print("PASS glide_warnings (%d rows of the lab glider's attitude within the Euler ranges)" % rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
