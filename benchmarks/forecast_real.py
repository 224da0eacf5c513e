#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The forecast on the real comet deployments' consecutive surfacings (docs/forecast.md, Benchmark).

comet-2019 (the default, --deployment comet-2019): comet-2019-222-02-154 and -156 (tests/data/real,
mission NSB3 in boards/missions/comet-nsb3) are two ~2.8 h dives of one deployment with fixes before each
dive and after each surfacing.
comet-2016 (--deployment comet-2016): comet-2016-174-05.csv (segments 000..009, 4.13 h), seven calls (the
file's start, five after 8-half-yo dives - the first 2 half yos -, one after a timer's climb; the yo tops'
brief fixes are no calls), flown with the mission reconstructed from its .dbd files
(boards/missions/comet-subex2016-reconstructed, README: not the flown mission); the forecast from the 6th
call's predecessor is printed, not scored (the timer is not in the mission). --deployment all: both, and
the combined tables (median, p90 by nearest rank, with and without each deployment's surfacing 0).
Each surfacing becomes a shore event (glider-shore-surfacing/1: the last fix before the dive, the dive time,
the glider's m_water_vx/vy after its update, its DR position before the first fix), written into a glider
folder holding what the shore would have had at that call; glider-forecast forecasts the next
surfacing, scored against the first fix after it (position) and the time the glider reached 1 m; the same
forecast options and vehicle (slocum_comet.toml) for every deployment.
The waypoint the glider flew to at each dive is its own (c_wpt_lat/lon, x_last_wpt_lat/lon in the .dbd
files of tests/data/real/dbd/comet-20xx, decoded with glider-convert); `--waypoint N` forces one.
Each forecast's position error is split into terms (docs/forecast.md, "Where the error comes from"):
  flight  = the baseline flight (water as the glider believed it) - the glider's own dead reckoning
            (both fly the believed water: what is left is heading law, speed through the water, waypoints;
            comet-2016: the DR's steps summed without its resets at the yo tops' fixes)
  current = (forecast current - the current the glider measured over the dive) x time under water
  time    = (forecast current - believed current) x (forecast - true time under water)
  rest    = error - the three (the runs' spread and median, the DR's own error)
With --check: comet-2019 (CTest forecast.real_comet_2019) exits 1 unless each forecast's current is nearer
the one the glider measured over the dive than persistence is, and within 0.1 m/s from surfacing 1 (two
estimates), and each forecast's time within 5 min of the glider's (the issue's time goal); comet-2016
(forecast.real_comet_2016) unless the waypoints are the glider's c_wpt (0 0 0 1 1 1), from surfacing 1 on
each forecast is within 0.5 km of the first fix and from surfacing 2 its current within 0.1 m/s of the
glider's next update,
and with --from-glider each 8-half-yo dive's time (from surfacings 1-4) within 5 min.
Usage: forecast_real.py --build BUILD_DIR [--source SOURCE_DIR] [--out DIR] [--runs N] [--waypoint N]
       [--deployment comet-2019|comet-2016|all]
       [--current-prior evidence|fixed|off] [--prior-position-sigma M] [--speed-correction] [--no-speed-correction] [--pitch-calibration]
       [--no-glider-dead-reckoning] [--no-depth-rate-calibration] [--depth-rate-drag] [--from-glider]
       [--tide FILE | --tide-leave-out CONSTITUENTS] [--check]
--tide FILE passes the pilot's tide table to every forecast; --tide-leave-out M2[,K1..] fits it for each forecast
from the same deployment's depth-averaged currents without the dive being scored (glider-forecast fit-tide
--exclude-from/--exclude-to), and flies without one where the fit refuses (printed: a record too short).
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
    return math.hypot(*offset_m(lat1, lon1, lat2, lon2))


def offset_m(lat1, lon1, lat2, lon2):
    """(east, north) of point 2 from point 1, metres (flat earth: a few km)."""
    r = 6371000.0
    return (math.radians(lon2 - lon1) * r * math.cos(math.radians(lat1)), math.radians(lat2 - lat1) * r)


def find_program(build, name):
    for root, _, files in os.walk(os.path.join(build, "tools")):
        if name in files:
            return os.path.join(root, name)
    raise SystemExit("%s not built in %s" % (name, build))


def mission_waypoints(goto_ma):
    """The goto list's waypoints as (lat, lon) in decimal degrees (the file gives lon lat in ddmm)."""
    out, inside = [], False
    with open(goto_ma) as f:
        for line in f:
            text = line.split("#")[0].strip()
            if line.strip().startswith("<start:waypoints>"):
                inside = True
            elif line.strip().startswith("<end:waypoints>"):
                inside = False
            elif inside and text:
                lon, lat = (float(v) for v in text.split()[:2])
                out.append((ddmm(lat), ddmm(lon)))
    return out


def active_waypoints(convert, dbd_dir, names, waypoints, dives):
    """The waypoint the glider flew to at each dive time, from its own c_wpt_lat/lon (logged when set)
    and x_last_wpt_lat/lon (the one reached, logged with the next c_wpt): a dive before the first
    c_wpt of the files flies to the waypoint reached at that first change."""
    rows = []
    for n in names:
        csv_path = os.path.join(tempdir, n + ".wpt.csv")
        subprocess.run([convert, os.path.join(dbd_dir, n + ".dbd"), "--quiet", "--out", csv_path, "--columns",
                        "c_wpt_lat,c_wpt_lon,x_last_wpt_lat,x_last_wpt_lon"], check=True, capture_output=True)
        rows += load(csv_path)

    def index(lat, lon):
        for i, (wlat, wlon) in enumerate(waypoints):
            if abs(ddmm(lat) - wlat) < 1e-6 and abs(ddmm(lon) - wlon) < 1e-6:
                return i
        raise SystemExit("waypoint %s %s is not in the goto list" % (lat, lon))

    changes = []  # (time, waypoint active from then on)
    first_before = None
    for r in rows:
        if r.get("c_wpt_lat") is not None and r.get("c_wpt_lon") is not None:
            if r["c_wpt_lat"] == 0.0 and r["c_wpt_lon"] == 0.0:
                continue  # the sensor's default, logged before the goto list set it (comet-2016's first row)
            if not changes and r.get("x_last_wpt_lat") is not None:
                first_before = index(r["x_last_wpt_lat"], r["x_last_wpt_lon"])
            changes.append((r["m_present_time"], index(r["c_wpt_lat"], r["c_wpt_lon"])))
    out = []
    for t in dives:
        active = first_before
        for when, w in changes:
            if when <= t:
                active = w
        if active is None:
            raise SystemExit("the .dbd files do not say which waypoint was active at %s" % utc(t))
        out.append(active)
    return out


def first_fix_time(convert, dbd_path):
    """When the glider had its first fix at the surfacing its file opens on: the file's first
    m_dr_postfix_time (seconds since that fix, logged with the m_water_vx/vy update) back from
    its row's time. The csv begins well after the glider came up (13 min on file 154)."""
    csv_path = os.path.join(tempdir, os.path.basename(dbd_path) + ".fix.csv")
    subprocess.run([convert, dbd_path, "--quiet", "--out", csv_path, "--columns", "m_dr_postfix_time"],
                   check=True, capture_output=True)
    for r in load(csv_path):
        if r.get("m_dr_postfix_time") is not None and r["m_dr_postfix_time"] > 0.0:
            return r["m_present_time"] - r["m_dr_postfix_time"]
    raise SystemExit("%s logs no m_dr_postfix_time" % dbd_path)


def forecast_options(a):
    """glider-forecast's options, the same for every deployment (no per-log tuning)."""
    return ((["--current-prior", a.current_prior] if a.current_prior else []) +
            (["--speed-correction"] if a.speed_correction else []) +
            (["--no-speed-correction"] if a.no_speed_correction else []) +
            (["--pitch-calibration"] if a.pitch_calibration else []) +
            (["--no-glider-dead-reckoning"] if a.no_glider_dead_reckoning else []) +
            (["--no-depth-rate-calibration"] if a.no_depth_rate_calibration else []) +
            (["--depth-rate-drag"] if a.depth_rate_drag else []) +
            (["--prior-position-sigma", str(a.prior_position_sigma)] if a.prior_position_sigma is not None else []) +
            (["--tide", a.tide] if a.tide else []))


def leave_out_tide(a, forecast, out, case):
    """The tide table fitted to the case's whole deployment but the dive it scores (None: the fit refused)."""
    d = os.path.join(out, case["dir"] + "_tide", case["glider"])
    shutil.rmtree(os.path.dirname(d), ignore_errors=True)
    os.makedirs(os.path.join(d, "logs"))
    for i, e in enumerate(case["deployment_events"]):
        with open(os.path.join(d, "logs", case["log_name"] % (i, i + 1)), "w") as f:
            json.dump(e, f, indent=2)
    table = os.path.join(os.path.dirname(d), "tide.toml")
    dive = case["events"][-1]["call_end_utc"]
    run = subprocess.run([forecast, "fit-tide", "--glider-dir", d, "--constituents", a.tide_leave_out,
                          "--exclude-from", dive, "--exclude-to", utc(case["truth"]["up"]), "--out", table],
                         capture_output=True, text=True)
    print("%sfrom surfacing %d: tide fitted without the dive %s-%s: %s" %
          (case["label"], case["k"], dive, utc(case["truth"]["up"]),
           "table %s" % table if run.returncode == 0 else "refused (%s)" % run.stderr.strip()))
    return table if run.returncode == 0 else None


def t_utc(s):
    return time.mktime(time.strptime(s, "%Y-%m-%dT%H:%M:%SZ")) - time.timezone


def write_from_glider(d, dives):
    """The dives' m_depth, m_pitch and m_heading the shore had by the call (4.5 s rows, as an .sbd carries them)."""
    os.makedirs(os.path.join(d, "from-glider"))
    for logged, until, name in dives:
        with open(os.path.join(d, "from-glider", name + ".sbd.csv"), "w") as f:
            f.write("m_present_time,m_depth,m_pitch,m_heading\n")
            for r in logged:
                if r["m_present_time"] <= until and r["m_depth"] is not None and r["m_pitch"] is not None:
                    heading = "" if r["m_heading"] is None else "%.5f" % r["m_heading"]
                    f.write("%.3f,%.3f,%.5f,%s\n" % (r["m_present_time"], r["m_depth"], r["m_pitch"], heading))


def run_case(a, forecast, vehicle, out, case):
    """Forecast one surfacing from the events before it and score it: returns the case's numbers.
    case: label, k (the surfacing forecast from), glider, mission (folder), events, waypoint,
    truth (up: time it reached 1 m, first: its first fix, dr_end: (lat, lon) of the glider's dead
    reckoning there, water: its m_water_vx/vy update), from_glider (dives for write_from_glider)."""
    d = os.path.join(out, case["dir"], case["glider"])
    shutil.rmtree(os.path.dirname(d), ignore_errors=True)
    os.makedirs(os.path.join(d, "logs"))
    shutil.copytree(case["mission"], os.path.join(d, "mission"), ignore=shutil.ignore_patterns("README.md"))
    for i, e in enumerate(case["events"]):
        with open(os.path.join(d, "logs", case["log_name"] % (i, i + 1)), "w") as f:
            json.dump(e, f, indent=2)
    if a.from_glider:
        write_from_glider(d, case["from_glider"])
    tide = []
    if a.tide_leave_out:
        table = leave_out_tide(a, forecast, out, case)
        tide = ["--tide", table] if table else []
    run = subprocess.run([forecast, "--glider-dir", d, "--vehicle", vehicle, "--runs", str(a.runs),
                          "--waypoint", str(case["waypoint"]), "--json"] + forecast_options(a) + tide,
                         capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        sys.exit(1)
    f = json.loads(run.stdout)
    up, first, water = case["truth"]["up"], case["truth"]["first"], case["truth"]["water"]
    lat, lon = ddmm(first["m_gps_lat"]), ddmm(first["m_gps_lon"])
    n = f["next_surfacing"]
    b = f["baseline"]
    e_pos = distance_m(n["lat_deg"], n["lon_deg"], lat, lon)
    b_pos = distance_m(b["lat_deg"], b["lon_deg"], lat, lon)
    e_t = abs(t_utc(n["time_utc"]) - up)
    b_t = abs(t_utc(b["time_utc"]) - up)
    moved = distance_m(f["from_fix"]["lat_deg"], f["from_fix"]["lon_deg"], lat, lon)
    print("%sfrom surfacing %d (%s): the glider moved %.0f m in %.1f h; forecast %.0f m, %+.0f s off; "
          "baseline %.0f m, %+.0f s off; current %s (%+.3f E %+.3f N); wall %.2f s" %
          (case["label"], case["k"], f["from_fix"]["utc"], moved, (up - t_utc(f["dive_utc"])) / 3600.0, e_pos,
           t_utc(n["time_utc"]) - up, b_pos, t_utc(b["time_utc"]) - up,
           f["current"]["method"], f["current"]["east_m_s"], f["current"]["north_m_s"], f["wall_s"]))
    # The error's terms, east and north, in the fix's frame.
    fx = f["from_fix"]
    dive_t = t_utc(f["dive_utc"])
    true_s, pred_s = up - dive_t, t_utc(n["time_utc"]) - dive_t
    truth = offset_m(fx["lat_deg"], fx["lon_deg"], lat, lon)
    pred = offset_m(fx["lat_deg"], fx["lon_deg"], n["lat_deg"], n["lon_deg"])
    base = offset_m(fx["lat_deg"], fx["lon_deg"], b["lat_deg"], b["lon_deg"])
    dr_end = offset_m(fx["lat_deg"], fx["lon_deg"], *case["truth"]["dr_end"])
    cp = (f["current"]["east_m_s"], f["current"]["north_m_s"])
    cb = (b["current_east_m_s"], b["current_north_m_s"])
    ct = (water["m_water_vx"], water["m_water_vy"])
    err = [pred[i] - truth[i] for i in range(2)]
    flight = [base[i] - dr_end[i] for i in range(2)]
    current = [(cp[i] - ct[i]) * true_s for i in range(2)]
    timing = [(cp[i] - cb[i]) * (pred_s - true_s) for i in range(2)]
    rest = [err[i] - flight[i] - current[i] - timing[i] for i in range(2)]
    print("  waypoint %d; error %.0f m = flight %.0f m (%+.0f E %+.0f N) + current %.0f m (%+.0f E %+.0f N; "
          "forecast %+.3f %+.3f, measured over the dive %+.3f %+.3f m/s) + time %.0f m + rest %.0f m" %
          (case["waypoint"], math.hypot(*err), math.hypot(*flight), flight[0], flight[1], math.hypot(*current),
           current[0], current[1], cp[0], cp[1], ct[0], ct[1], math.hypot(*timing), math.hypot(*rest)))
    return {"label": case["label"], "k": case["k"], "pos": e_pos, "time": e_t, "base_pos": b_pos, "base_time": b_t,
            "signed_time": t_utc(n["time_utc"]) - up, "base_signed_time": t_utc(b["time_utc"]) - up,
            "current_off": math.hypot(cp[0] - ct[0], cp[1] - ct[1]),
            "persistence_off": math.hypot(cb[0] - ct[0], cb[1] - ct[1]),
            "forecast_dive_s": pred_s, "true_dive_s": true_s, "current": cp, "persistence": cb,
            "fix_current": case["truth"].get("fix_current"),
            # the vectors (east, north m from the fix the glider dived from) benchmarks/forecast_attribution.py splits
            "error_en": err, "forecast_en": pred, "truth_en": truth, "flight_en": flight,
            "dr_end_en": dr_end, "measured": ct}


def comet_2019_cases(a, real, convert):
    """comet-2019-222-02-154 and -156: surfacings [0] before 154's dive, [1] between, [2] after 156."""
    nsb3 = os.path.join(a.source, "boards", "missions", "comet-nsb3")
    files = [load(os.path.join(real, n + ".csv")) for n in ("comet-2019-222-02-154", "comet-2019-222-02-156")]
    fix0, dive0, water0, start0 = dive_start(files[0])
    up1, first1, dr1, water1 = surfacing(files[0])
    fix1, dive1, _, _ = dive_start(files[1])
    up2, first2, dr2, water2 = surfacing(files[1])
    dbd_dir = os.path.join(real, "dbd", "comet-2019")
    # Surfacing 0's call: file 154 opens 878 s after the glider's first fix there (its m_dr_postfix_time);
    # the glider was up from that fix (a shore event's call_start: "the glider is up, its fix from then"),
    # not from the file's first row. Surfacing 1's call starts when it reached 1 m (in file 154).
    call0 = min(start0, first_fix_time(convert, os.path.join(dbd_dir, "comet-2019-222-02-154.dbd")))
    events = [event("comet", call0, dive0, fix0, None, water0, "nsb3.mi"),
              event("comet", up1, dive1, fix1, dr1, water1, "nsb3.mi")]
    truths = [(up1, first1, dr1, water1), (up2, first2, dr2, water2)]
    # The whole deployment as the shore has it after file 156 (its last call: the file's end), for the tide's fit.
    deployment = events + [event("comet", up2, files[1][-1]["m_present_time"], first2, dr2, water2, "nsb3.mi")]
    if a.waypoint is not None:
        wpts = [a.waypoint, a.waypoint]
    else:
        # The waypoint is the glider's own (its .dbd's c_wpt: dive 154 flew to waypoint 1, 54.30 N 7.43 E,
        # reached by DR 6918 s in, then waypoint 0; dive 156 to waypoint 0, 54.558 N 7.217 E).
        wpts = active_waypoints(convert, dbd_dir,
                                ["comet-2019-222-02-%d" % n for n in (154, 155, 156)],
                                mission_waypoints(os.path.join(nsb3, "mafiles", "goto_l10.ma")), [dive0, dive1])
    cases = []
    for k in range(2):
        up, first, dr, water = truths[k]
        cases.append({"label": "", "k": k, "dir": "from%d" % k, "glider": "comet", "mission": nsb3,
                      "log_name": "2019082%d_%04d.surfacing.json", "events": events[:k + 1], "waypoint": wpts[k],
                      "deployment_events": deployment,
                      "truth": {"up": up, "first": first, "water": water,
                                "dr_end": (ddmm(dr["m_lat"]), ddmm(dr["m_lon"]))},
                      "from_glider": ((files[0], up1, "comet-2019-222-02-154"),)[:k]})
    return cases


def comet_2016_surfacings(rows):
    """comet-2016-174-05 (one CSV of segments 000..009): the glider surfaced with a call where its
    m_water_vx/vy was updated; in between it turned at 0-0.4 m at each yo top and logged brief GPS
    fixes there (its DR reset by them), but made no call and kept its current estimate.
    Returns, per call: arrival (reached 1 m; the file's first row for surfacing 0), the first fix
    after it, the glider's DR just before that fix, its updated current, its last fix before the dive
    and the dive's start (first row deeper than 2 m), and the pure dead reckoning of the dive that
    ended there (the DR's steps summed without the yo tops' resets: the 'flight' term's reference)."""
    updates = [i for i, r in enumerate(rows) if r["m_water_vx"] is not None]
    groups = []
    for i in updates:
        if groups and rows[i]["m_present_time"] - rows[groups[-1][-1]]["m_present_time"] < 300.0:
            groups[-1].append(i)
        else:
            groups.append([i])
    calls = []
    for g in groups:
        deep = [j for j in range(g[0]) if rows[j]["m_depth"] is not None and rows[j]["m_depth"] > 2.0]
        if not deep:
            start = 0
            arrival = rows[0]["m_present_time"]
        else:
            start = deep[-1]
            arrival = next(r for r in rows[start:] if r["m_depth"] is not None and r["m_depth"] < 1.0)["m_present_time"]
        first = next(r for r in rows[start:] if r["m_gps_lat"] is not None)
        dr = [r for r in rows[start:] if r["m_lat"] is not None and r["m_present_time"] < first["m_present_time"]]
        dive = next((j for j in range(g[-1], len(rows)) if rows[j]["m_depth"] is not None and rows[j]["m_depth"] > 2.0),
                    None)
        water = rows[g[-1]]
        fix = None
        if dive is not None:
            water = [r for r in rows[g[0]:dive] if r["m_water_vx"] is not None][-1]
            fix = [r for r in rows[g[0]:dive] if r["m_gps_lat"] is not None][-1]
        calls.append({"arrival": arrival, "first": first, "dr": dr[-1] if dr else None, "water": water, "fix": fix,
                      "dive": rows[dive]["m_present_time"] if dive is not None else None, "start_index": start,
                      "dive_index": dive})
    # The pure DR of each dive: from the fix it dived from, the DR's steps without its resets to a fix.
    for k in range(1, len(calls)):
        before, c = calls[k - 1], calls[k]
        lat, lon = ddmm(before["fix"]["m_gps_lat"]), ddmm(before["fix"]["m_gps_lon"])
        prev = None
        for r in rows[before["dive_index"]:]:
            if r["m_present_time"] >= c["first"]["m_present_time"]:
                break
            if r["m_lat"] is None:
                continue
            here = (ddmm(r["m_lat"]), ddmm(r["m_lon"]))
            reset = r["m_gps_lat"] is not None and abs(r["m_lat"] - r["m_gps_lat"]) < 1e-6
            if prev is not None and not reset:
                lat += here[0] - prev[0]
                lon += here[1] - prev[1]
            prev = here
        c["pure_dr"] = (lat, lon)
        # The current the fixes say over the dive: the glider's carried estimate plus the pure DR's miss
        # of the first fix over the time from the dive's fix (the glider's own m_water_vx lags it here).
        under_s = c["first"]["m_present_time"] - before["fix"]["m_present_time"]
        e, n = offset_m(lat, lon, ddmm(c["first"]["m_gps_lat"]), ddmm(c["first"]["m_gps_lon"]))
        c["fix_current"] = (before["water"]["m_water_vx"] + e / under_s, before["water"]["m_water_vy"] + n / under_s)
    return calls


def comet_2016_cases(a, real, convert):
    """comet-2016-174-05: 7 calls (0: the file's start; 1-5 after 8 half yos each, the first dive 2 half
    yos; 6 after a timer's climb), forecast from each of 0..5 with the reconstructed SUBEX mission."""
    mission = os.path.join(a.source, "boards", "missions", "comet-subex2016-reconstructed")
    rows = load(os.path.join(real, "comet-2016-174-05.csv"))
    calls = comet_2016_surfacings(rows)
    if len(calls) != 7:
        raise SystemExit("comet-2016: %d calls found, 7 expected" % len(calls))
    events = []
    for k, c in enumerate(calls[:-1]):
        events.append(event("comet", c["arrival"], c["dive"], c["fix"], c["dr"] if k > 0 else None, c["water"],
                            "subex.mi"))
    if a.waypoint is not None:
        wpts = [a.waypoint] * (len(calls) - 1)
    else:
        dbd_dir = os.path.join(real, "dbd", "comet-2016")
        wpts = active_waypoints(convert, dbd_dir, ["comet-2016-174-05-%03d" % n for n in range(10)],
                                mission_waypoints(os.path.join(mission, "mafiles", "goto_l10.ma")),
                                [c["dive"] for c in calls[:-1]])
    cases = []
    for k in range(len(calls) - 1):
        nxt = calls[k + 1]
        cases.append({"label": "comet-2016 ", "k": k, "dir": "comet2016_from%d" % k, "glider": "comet",
                      "mission": mission, "log_name": "2016062%d_%04d.surfacing.json", "events": events[:k + 1],
                      "deployment_events": events + [event("comet", calls[-1]["arrival"], rows[-1]["m_present_time"],
                                                           calls[-1]["first"], calls[-1]["dr"], calls[-1]["water"],
                                                           "subex.mi")],
                      "waypoint": wpts[k],
                      "truth": {"up": nxt["arrival"], "first": nxt["first"], "water": nxt["water"],
                                "dr_end": nxt["pure_dr"], "fix_current": nxt["fix_current"]},
                      "from_glider": [(rows[calls[j]["dive_index"]:calls[j + 1]["start_index"] + 1],
                                       calls[j + 1]["arrival"], "comet-2016-174-05-dive%d" % j) for j in range(k)],
                      # surfacing 6 came up by a timer (x_surface_active 4 at 15 m in a climb) the
                      # reconstructed mission does not hold: scored apart
                      "timer": k + 1 == len(calls) - 1})
    return cases


def median(v):
    v = sorted(v)
    return v[len(v) // 2] if len(v) % 2 else 0.5 * (v[len(v) // 2 - 1] + v[len(v) // 2])


def p90(v):
    """Nearest rank: the smallest value with at least 90 % of the values at or below it."""
    v = sorted(v)
    return v[max(0, math.ceil(0.9 * len(v)) - 1)]


def table(title, rows):
    print("\n%s: %d forecasts" % (title, len(rows)))
    print("| | position median | position p90 (nearest rank) | position max | time median | time p90 |")
    print("|---|---|---|---|---|---|")
    for name, pk, tk in (("forecast", "pos", "time"), ("baseline (last current persists)", "base_pos", "base_time")):
        print("| %s | %.2f km | %.2f km | %.2f km | %.1f min | %.1f min |" %
              (name, median([r[pk] for r in rows]) / 1000, p90([r[pk] for r in rows]) / 1000,
               max(r[pk] for r in rows) / 1000, median([r[tk] for r in rows]) / 60, p90([r[tk] for r in rows]) / 60))
    mf, mb = median([r["pos"] for r in rows]), median([r["base_pos"] for r in rows])
    pf, pb = p90([r["pos"] for r in rows]), p90([r["base_pos"] for r in rows])
    print("position vs baseline: median %+.0f %%, p90 %+.0f %% (negative: better than persistence; goal <= -30 %%)" %
          (100.0 * (mf - mb) / mb, 100.0 * (pf - pb) / pb))


def arguments(description):
    """The benchmark's options (benchmarks/forecast_attribution.py takes the same)."""
    p = argparse.ArgumentParser(description=description)
    p.add_argument("--build", required=True)
    p.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p.add_argument("--out", default=None)
    p.add_argument("--runs", type=int, default=200)
    p.add_argument("--deployment", choices=["comet-2019", "comet-2016", "all"], default="comet-2019",
                   help="which real deployment's surfacings (all: both and the combined table)")
    p.add_argument("--waypoint", type=int, default=None, help="force this active waypoint for every forecast")
    p.add_argument("--current-prior", default=None, help="glider-forecast's --current-prior (evidence, fixed, off)")
    p.add_argument("--speed-correction", action="store_true", help="glider-forecast's --speed-correction")
    p.add_argument("--no-speed-correction", action="store_true", help="glider-forecast's --no-speed-correction")
    p.add_argument("--pitch-calibration", action="store_true", help="glider-forecast's --pitch-calibration")
    p.add_argument("--no-glider-dead-reckoning", action="store_true",
                   help="glider-forecast's --no-glider-dead-reckoning")
    p.add_argument("--no-depth-rate-calibration", action="store_true",
                   help="glider-forecast's --no-depth-rate-calibration")
    p.add_argument("--depth-rate-drag", action="store_true", help="glider-forecast's --depth-rate-drag")
    p.add_argument("--prior-position-sigma", type=float, default=None,
                   help="glider-forecast's --prior-position-sigma (m; 0: the rule before session 37)")
    p.add_argument("--from-glider", action="store_true",
                   help="put the dives' m_depth, m_pitch and m_heading the shore had by each call (4.5 s rows, as an .sbd "
                        "carries them) in from-glider/: the speed term reads the pitch sensor's scale from them")
    p.add_argument("--tide", default=None, help="glider-forecast's --tide FILE (the pilot's tide table)")
    p.add_argument("--tide-leave-out", default=None, metavar="CONSTITUENTS",
                   help="fit the tide table (these constituents, e.g. M2) for each forecast from its deployment's "
                        "currents without the dive scored; no table where the fit refuses")
    p.add_argument("--check", action="store_true", help="test mode: the checks above, PASS/FAIL line")
    return p


def main():
    a = arguments(__doc__.splitlines()[0]).parse_args()
    out = a.out or os.path.join(a.build, "benchmark", "forecast_real")
    real = os.path.join(a.source, "tests", "data", "real")
    vehicle = os.path.join(a.source, "boards", "vehicles", "slocum_comet.toml")
    forecast = find_program(a.build, "glider-forecast")
    global tempdir
    tempdir = os.path.join(out, "dbd")
    os.makedirs(tempdir, exist_ok=True)
    convert = find_program(a.build, "glider-convert")
    results_2019, results_2016 = [], []
    if a.deployment in ("comet-2019", "all"):
        results_2019 = [run_case(a, forecast, vehicle, out, c) for c in comet_2019_cases(a, real, convert)]
    if a.deployment in ("comet-2016", "all"):
        cases = comet_2016_cases(a, real, convert)
        results_2016 = [dict(run_case(a, forecast, vehicle, out, c), timer=c["timer"]) for c in cases]

    failures = []
    if results_2019:
        rows = results_2019
        for r in rows:
            if not r["current_off"] < r["persistence_off"]:
                failures.append("from surfacing %d the current is %.3f m/s off, persistence %.3f" %
                                (r["k"], r["current_off"], r["persistence_off"]))
            if r["k"] == 1 and not r["current_off"] < 0.1:
                failures.append("from surfacing 1 the current is %.3f m/s off (0.1 allowed)" % r["current_off"])
            # The time goal (5 min) on each forecast: the when_secs clock counted from its firing and
            # surfacing 0's call from the glider's first fix (1059 s late before both, 292 s from surfacing 1).
            if not r["time"] <= 300.0:
                failures.append("from surfacing %d the time is %.0f s off (300 allowed)" % (r["k"], r["time"]))
        print("\nreal comet-2019: %d forecasts" % len(rows))
        print("| | position median | position max | time median |\n|---|---|---|---|")
        print("| forecast | %.2f km | %.2f km | %.1f min |" % (median([r["pos"] for r in rows]) / 1000,
                                                             max(r["pos"] for r in rows) / 1000,
                                                             median([r["time"] for r in rows]) / 60))
        print("| baseline (last current persists) | %.2f km | %.2f km | %.1f min |" %
              (median([r["base_pos"] for r in rows]) / 1000, max(r["base_pos"] for r in rows) / 1000,
               median([r["base_time"] for r in rows]) / 60))
    if results_2016:
        scored = [r for r in results_2016 if not r["timer"]]
        print("\ncomet-2016 per forecast (the time signed, + late; dive: forecast / true time under water)")
        print("| from | position | baseline | time | baseline time | dive forecast/true | current off | persistence off "
              "| current: forecast / the fixes say (E, N m/s) | off the fixes': forecast / persistence |")
        print("|---|---|---|---|---|---|---|---|---|---|")
        for r in results_2016:
            fc = r["fix_current"]
            print("| %d%s | %.2f km | %.2f km | %+.0f s | %+.0f s | %.0f / %.0f s | %.3f m/s | %.3f m/s "
                  "| %+.3f %+.3f / %+.3f %+.3f | %.3f / %.3f |" %
                  (r["k"], " (timer, not scored)" if r["timer"] else "", r["pos"] / 1000, r["base_pos"] / 1000,
                   r["signed_time"], r["base_signed_time"], r["forecast_dive_s"], r["true_dive_s"],
                   r["current_off"], r["persistence_off"], r["current"][0], r["current"][1], fc[0], fc[1],
                   math.hypot(r["current"][0] - fc[0], r["current"][1] - fc[1]),
                   math.hypot(r["persistence"][0] - fc[0], r["persistence"][1] - fc[1])))
        table("real comet-2016 (surfacings 0-4 forecast, the 8-half-yo dives' ends)", scored)
        table("real comet-2016 without surfacing 0", [r for r in scored if r["k"] > 0])
        # The solid part (forecast.real_comet_2016), what holds with the forecast's rules as they are:
        # the log read as the glider flew it (its own waypoints), and from surfacing 2 on (three estimates,
        # the first dive's outlier no longer the last) each forecast within 0.5 km of the glider's first fix
        # and its current within 0.1 m/s of the glider's update at that surfacing. Not checked, because
        # they fail (docs/forecast.md): the times without --from-glider (5.3-5.7 min early: the vehicle
        # file's flight) and the current nearer than persistence's (the glider's own estimates converge from above).
        if a.waypoint is None and [c["waypoint"] for c in cases] != [0, 0, 0, 1, 1, 1]:
            failures.append("comet-2016 waypoints %s, the glider's c_wpt says 0 0 0 1 1 1" %
                            [c["waypoint"] for c in cases])
        # From surfacing 1 too since session 37 (each estimate's position error over its segment: the
        # 606 s dive's estimate no longer extrapolated as a tide, 2.03 -> 0.24 km; docs/forecast.md).
        for r in scored:
            if r["k"] >= 1 and not r["pos"] <= 500.0:
                failures.append("comet-2016 from surfacing %d the position is %.0f m off (500 allowed)" %
                                (r["k"], r["pos"]))
            if r["k"] >= 2 and not r["current_off"] < 0.1:
                failures.append("comet-2016 from surfacing %d the current is %.3f m/s off (0.1 allowed)" %
                                (r["k"], r["current_off"]))
            # With the dives' depths and pitch sent home the depth-rate calibration flies the glider's slower
            # glide (docs/forecast.md): every 8-half-yo dive's end within 5 min (5.3-5.7 min early without).
            if a.from_glider and r["k"] >= 1 and not abs(r["signed_time"]) <= 300.0:
                failures.append("comet-2016 from surfacing %d the time is %+.0f s off (300 allowed with "
                                "--from-glider)" % (r["k"], r["signed_time"]))
    if results_2019 and results_2016:
        scored = results_2019 + [r for r in results_2016 if not r["timer"]]
        table("real comet-2019 + comet-2016 combined", scored)
        table("real combined without surfacing 0 of each deployment", [r for r in scored if r["k"] > 0])
    if a.check:
        name = {"comet-2019": "real_comet_2019", "comet-2016": "real_comet_2016", "all": "real_comets"}[a.deployment]
        print("FAIL %s: " % name + "; ".join(failures) if failures else "PASS %s" % name)
        sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
