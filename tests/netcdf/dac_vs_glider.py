#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""dac_vs_glider.py CONVERT METADATA VEHICLE OUTDIR INPUT...: the depth-averaged current of
the OG1.0 file (flight model, DEPTH_AVG_CURR_*) against the Slocum's own estimate of the
same dive (m_water_vx/vy, reported after it surfaces, from its own dead reckoning): two
independent estimates; they must agree within twice the file's stated uncertainty."""
import math
import os
import subprocess
import sys

convert, metadata, vehicle, outdir, inputs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
os.makedirs(outdir, exist_ok=True)
csv_path, nc_path = os.path.join(outdir, "dac.csv"), os.path.join(outdir, "dac.nc")
subprocess.run([convert, "--quiet", "--columns", "m_water_vx,m_water_vy", "--out", csv_path] + inputs, check=True)
subprocess.run([convert, "--quiet", "--format", "og1", "--metadata", metadata, "--vehicle", vehicle, "--out",
                nc_path] + inputs, check=True)
rows = [l.rstrip("\n").split(",") for l in open(csv_path) if not l.startswith("#")]
h = rows[0]
reports = [(float(r[h.index("m_present_time")]), float(r[h.index("m_water_vx")]), float(r[h.index("m_water_vy")]))
           for r in rows[1:] if r[h.index("m_water_vx")] != ""]
names = ["TIME", "DEPTH_AVG_CURR_EAST", "DEPTH_AVG_CURR_NORTH", "DEPTH_AVG_CURR_UNCERTAINTY"]
dump = subprocess.run(["ncdump", "-p", "9,17", "-v", ",".join(names), nc_path], check=True, capture_output=True,
                      text=True).stdout.split("data:")[1]
v = {n: [math.nan if x.strip() == "_" else float(x) for x in
         dump.split(f" {n} =")[1].split(";")[0].replace("\n", " ").split(",")] for n in names}
# Each dive's estimate (constant over its samples) and the time its samples end.
dives = []
for i, east in enumerate(v["DEPTH_AVG_CURR_EAST"]):
    if math.isnan(east):
        continue
    key = (east, v["DEPTH_AVG_CURR_NORTH"][i], v["DEPTH_AVG_CURR_UNCERTAINTY"][i])
    if dives and dives[-1][0] == key:
        dives[-1][1] = v["TIME"][i]
    else:
        dives.append([key, v["TIME"][i]])
compared = 0
failed = False
for (east, north, sigma), end in dives:
    after = [r for r in reports if end - 60 <= r[0] <= end + 1800]  # the glider's report at that surfacing
    if not after:
        continue
    _, gx, gy = after[0]
    diff = math.hypot(east - gx, north - gy)
    ok = diff <= 2 * sigma
    print(f"dive ending {end:.0f}: model ({east:+.3f}, {north:+.3f}) +- {sigma:.3f} m/s, glider ({gx:+.3f}, "
          f"{gy:+.3f}): difference {diff:.3f} m/s {'ok' if ok else 'MORE THAN 2 SIGMA'}")
    compared += 1
    failed |= not ok
print(f"{compared} dive(s) compared")
sys.exit(1 if failed or compared == 0 else 0)
