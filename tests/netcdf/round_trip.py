#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""round_trip.py CONVERT METADATA OUTDIR INPUT...: the OG1.0 file's values equal
the CSV conversion's (glider-convert, same inputs), read back with the NetCDF
library's ncdump at full precision (-p 9,17):
  - double variables (TIME, DEPTH, LATITUDE_GPS/LONGITUDE_GPS): to the CSV's own
    print precision (time %.5f: 5e-6 s plus one double ulp at 1.5e9 s, 2.4e-7 s; 4-byte sensors %.7g: 5e-7 relative;
    NMEA -> decimal degrees of the 8-byte GPS values, the log's repeats of the last fix dropped: 1e-9 deg);
  - float variables (TEMP, PRES, CNDC, PITCH): float32 of the unit-converted value,
    i.e. within 2 float32 epsilons (2.4e-7) plus the CSV's 7-digit print (5e-7), relative;
  - fill exactly where the CSV field is empty."""
import math
import os
import subprocess
import sys

import struct

convert, metadata, outdir, inputs = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
os.makedirs(outdir, exist_ok=True)
csv_path, nc_path = os.path.join(outdir, "rt.csv"), os.path.join(outdir, "rt.nc")
subprocess.run([convert, "--quiet", "--out", csv_path] + inputs, check=True)
subprocess.run([convert, "--quiet", "--format", "og1", "--metadata", metadata, "--out", nc_path] + inputs, check=True)

rows = [l.rstrip("\n") for l in open(csv_path) if not l.startswith("#")]
header = rows[0].split(",")
table = [r.split(",") for r in rows[1:]]


def column(name):
    i = header.index(name)
    return [float(r[i]) if r[i] != "" else math.nan for r in table]


def nmea(x):
    if math.isnan(x):
        return math.nan
    sign = -1.0 if x < 0 else 1.0
    x = abs(x)
    degrees = math.floor(x / 100.0)
    return sign * (degrees + (x - degrees * 100.0) / 60.0)


names = ["TIME", "DEPTH", "LATITUDE_GPS", "LONGITUDE_GPS", "TEMP", "PRES", "CNDC", "PITCH"]
dump = subprocess.run(["ncdump", "-p", "9,17", "-v", ",".join(names), nc_path], check=True, capture_output=True,
                      text=True).stdout.split("data:")[1]
fills = {"TIME": -1.0, "DEPTH": -9999.9, "LATITUDE_GPS": -9999.9, "LONGITUDE_GPS": -9999.9}
values = {}
for name in names:
    text = dump.split(f" {name} =")[1].split(";")[0].replace("\n", " ")
    values[name] = [math.nan if v.strip() == "_" else float(v) for v in text.split(",")]

deg = 180.0 / math.pi


def new_fixes(lat, lon):
    """The log repeats the last fix ("same value" records): only a new position is a fix."""
    out_lat, out_lon, last = [], [], None
    for a, b in zip(lat, lon):
        fix = None if math.isnan(a) or math.isnan(b) else (a, b)
        out_lat.append(a if fix is not None and fix != last else math.nan)
        out_lon.append(b if fix is not None and fix != last else math.nan)
        last = fix if fix is not None else last
    return out_lat, out_lon


gps_lat, gps_lon = new_fixes([nmea(x) for x in column("m_gps_lat")], [nmea(x) for x in column("m_gps_lon")])
expected = {
    "TIME": (column("m_present_time"), 5e-6 + 2.4e-7, 0.0),
    "DEPTH": (column("m_depth"), 0.0, 5e-7),
    "LATITUDE_GPS": (gps_lat, 1e-9, 0.0),
    "LONGITUDE_GPS": (gps_lon, 1e-9, 0.0),
    "TEMP": (column("sci_water_temp"), 0.0, 7.4e-7),
    "PRES": ([x * 10 for x in column("sci_water_pressure")], 0.0, 7.4e-7),
    "CNDC": ([x * 10 for x in column("sci_water_cond")], 0.0, 7.4e-7),
    "PITCH": ([x * deg for x in column("m_pitch")], 1e-6, 7.4e-7),
}
failed = False
for name, (want, absolute, relative) in expected.items():
    got = values[name]
    fill = fills.get(name, struct.unpack("f", struct.pack("f", -9999.9))[0])
    assert len(got) == len(want), f"{name}: {len(got)} values, the CSV has {len(want)} rows"
    worst, bad = 0.0, 0
    for g, w in zip(got, want):
        if math.isnan(w):
            bad += not (math.isnan(g) or g == fill)
            continue
        error = abs(g - w)
        worst = max(worst, error / max(abs(w), 1e-30))
        bad += error > absolute + relative * abs(w)
    print(f"{name}: {len(got)} values, worst relative error {worst:.2e}, {bad} outside tolerance")
    failed |= bad > 0
sys.exit(1 if failed else 0)
