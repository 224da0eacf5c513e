#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The forecast on the real comet deployment's consecutive surfacings (docs/forecast.md, Benchmark).

comet-2019-222-02-154 and -156 (tests/data/real, mission NSB3 in boards/missions/comet-nsb3) are two
~2.8 h dives of one deployment with fixes before each dive and after each surfacing. Each surfacing
becomes a shore event (glider-shore-surfacing/1: the last fix before the dive, the dive time, the
glider's m_water_vx/vy after its update, its DR position before the first fix), written into a glider
folder holding what the shore would have had at that call; glider-forecast forecasts the next
surfacing, scored against the first fix after it (position) and the time the glider reached 1 m.
Usage: forecast_real.py --build BUILD_DIR [--source SOURCE_DIR] [--out DIR] [--runs N]
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import time


def ddmm(text):
    v = float(text)
    sign = -1.0 if v < 0 else 1.0
    v = abs(v)
    return sign * (math.floor(v / 100.0) + (v - 100.0 * math.floor(v / 100.0)) / 60.0)


def utc(t):
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime(round(t)))


def load(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    rows = []
    for row in csv.DictReader(lines):
        rows.append({k: (float(v) if v != "" else None) for k, v in row.items()})
    return rows


def dive_start(rows):
    """The fixes before the dive, and the time the dive began (first row deeper than 2 m)."""
    for i, r in enumerate(rows):
        if r["m_depth"] is not None and r["m_depth"] > 2.0:
            fixes = [x for x in rows[:i] if x["m_gps_lat"] is not None]
            water = [x for x in rows[:i] if x["m_water_vx"] is not None]
            return fixes[-1], r["m_present_time"], water[-1] if water else None, rows[0]["m_present_time"]
    raise SystemExit("no dive")


def surfacing(rows):
    """The end of the file's dive: when it reached 1 m, its first fix, the DR before it, the updated current."""
    deep = max(i for i, r in enumerate(rows) if r["m_depth"] is not None and r["m_depth"] > 2.0)
    up = next(r for r in rows[deep:] if r["m_depth"] is not None and r["m_depth"] < 1.0)
    first_fix = next(r for r in rows[deep:] if r["m_gps_lat"] is not None)
    dr = [r for r in rows[deep:] if r["m_lat"] is not None and r["m_present_time"] < first_fix["m_present_time"]]
    dr = dr[-1] if dr else [r for r in rows[:deep] if r["m_lat"] is not None][-1]
    water = [r for r in rows[deep:] if r["m_water_vx"] is not None]
    return up["m_present_time"], first_fix, dr, water[-1] if water else None


def event(glider, start, end, fix, dr, water, mission):
    e = {"schema": "glider-shore-surfacing/1", "glider": glider, "vehicle_name": glider,
         "call_start_utc": utc(start), "call_end_utc": utc(end), "mission": {"name": mission},
         "gps": {"kind": "gps", "lat_deg": ddmm(fix["m_gps_lat"]), "lon_deg": ddmm(fix["m_gps_lon"])},
         "sensors": []}
    if dr is not None:
        e["dr"] = {"kind": "dr", "lat_deg": ddmm(dr["m_lat"]), "lon_deg": ddmm(dr["m_lon"])}
    if water is not None:
        e["sensors"] = [{"name": "m_water_vx", "unit": "m/s", "value": water["m_water_vx"]},
                        {"name": "m_water_vy", "unit": "m/s", "value": water["m_water_vy"]}]
    return e


def distance_m(lat1, lon1, lat2, lon2):
    r = 6371000.0
    return math.hypot(math.radians(lon2 - lon1) * r * math.cos(math.radians(lat1)), math.radians(lat2 - lat1) * r)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", required=True)
    p.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p.add_argument("--out", default=None)
    p.add_argument("--runs", type=int, default=200)
    a = p.parse_args()
    out = a.out or os.path.join(a.build, "benchmark", "forecast_real")
    real = os.path.join(a.source, "tests", "data", "real")
    nsb3 = os.path.join(a.source, "boards", "missions", "comet-nsb3")
    vehicle = os.path.join(a.source, "boards", "vehicles", "slocum_comet.toml")
    forecast = os.path.join(a.build, "tools", "shore", "forecast", "glider-forecast")
    files = [load(os.path.join(real, n + ".csv")) for n in ("comet-2019-222-02-154", "comet-2019-222-02-156")]
    # Surfacings: [0] before 154's dive, [1] between 154 and 156, [2] after 156.
    fix0, dive0, water0, start0 = dive_start(files[0])
    up1, first1, dr1, water1 = surfacing(files[0])
    fix1, dive1, _, _ = dive_start(files[1])
    up2, first2, dr2, water2 = surfacing(files[1])
    events = [event("comet", start0, dive0, fix0, None, water0, "nsb3.mi"),
              event("comet", up1, dive1, fix1, dr1, water1, "nsb3.mi")]
    truths = [(up1, first1), (up2, first2)]
    rows = []
    for k in range(2):
        d = os.path.join(out, "from%d" % k, "comet")
        shutil.rmtree(os.path.dirname(d), ignore_errors=True)
        os.makedirs(os.path.join(d, "logs"))
        shutil.copytree(nsb3, os.path.join(d, "mission"), ignore=shutil.ignore_patterns("README.md"))
        for i, e in enumerate(events[:k + 1]):
            with open(os.path.join(d, "logs", "2019082%d_%04d.surfacing.json" % (i, i + 1)), "w") as f:
                json.dump(e, f, indent=2)
        # Both dives fly to the goto list's first waypoint (c_heading 241-305 deg and 7-12 deg: north-west
        # to 54.558 N 7.217 E); the history holds no fix of an earlier arrival, so it is given.
        run = subprocess.run([forecast, "--glider-dir", d, "--vehicle", vehicle, "--runs", str(a.runs),
                              "--waypoint", "0", "--json"], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout, run.stderr)
            sys.exit(1)
        f = json.loads(run.stdout)
        up, first = truths[k]
        lat, lon = ddmm(first["m_gps_lat"]), ddmm(first["m_gps_lon"])
        n = f["next_surfacing"]
        b = f["baseline"]
        e_pos = distance_m(n["lat_deg"], n["lon_deg"], lat, lon)
        b_pos = distance_m(b["lat_deg"], b["lon_deg"], lat, lon)
        def t(s):
            return time.mktime(time.strptime(s, "%Y-%m-%dT%H:%M:%SZ")) - time.timezone
        e_t = abs(t(n["time_utc"]) - up)
        b_t = abs(t(b["time_utc"]) - up)
        moved = distance_m(f["from_fix"]["lat_deg"], f["from_fix"]["lon_deg"], lat, lon)
        print("from surfacing %d (%s): the glider moved %.0f m in %.1f h; forecast %.0f m, %.0f s off; "
              "baseline %.0f m, %.0f s off; current %s (%+.3f E %+.3f N); wall %.2f s" %
              (k, f["from_fix"]["utc"], moved, (up - t(f["dive_utc"])) / 3600.0, e_pos, e_t, b_pos, b_t,
               f["current"]["method"], f["current"]["east_m_s"], f["current"]["north_m_s"], f["wall_s"]))
        rows.append((e_pos, e_t, b_pos, b_t))
    med = lambda v: sorted(v)[len(v) // 2] if len(v) % 2 else 0.5 * sum(sorted(v)[len(v) // 2 - 1:len(v) // 2 + 1])
    print("\nreal comet-2019: %d forecasts" % len(rows))
    print("| | position median | position max | time median |\n|---|---|---|---|")
    print("| forecast | %.2f km | %.2f km | %.1f min |" % (med([r[0] for r in rows]) / 1000, max(r[0] for r in rows) / 1000,
                                                         med([r[1] for r in rows]) / 60))
    print("| baseline (last current persists) | %.2f km | %.2f km | %.1f min |" %
          (med([r[2] for r in rows]) / 1000, max(r[2] for r in rows) / 1000, med([r[3] for r in rows]) / 60))


if __name__ == "__main__":
    main()
