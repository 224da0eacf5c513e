#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""TEST FIXTURE, not the health or forecast program: writes the files those
programs own (CONTRACTS.md: health/health.json "glider-health/1",
forecast/forecast.json "glider-forecast/1") with values the test chooses, so
the console's tests do not depend on what glider-health and glider-forecast
conclude from a short SIL flight (and run on a branch without them). Each file
is written to a temporary in the same folder and renamed, as the contract says."""
import datetime
import json
import os


def utc(seconds_from_now=0.0):
    t = datetime.datetime.now(datetime.timezone.utc) + datetime.timedelta(seconds=seconds_from_now)
    return t.strftime("%Y-%m-%dT%H:%M:%SZ")


def _write(path, value):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".tmp")
    with open(tmp, "w") as f:
        json.dump(value, f, indent=1)
    os.rename(tmp, path)


def write_health(glider_dir, glider, state, drag_ratio=None, vehicle=None):
    """state "ok" | "alert" | "cannot judge"; with drag_ratio an effect drag_change rising to it; with vehicle
    (a vehicle file) health/vehicle.toml, the forecast's input (CONTRACTS.md), a copy of it."""
    if vehicle is not None:
        os.makedirs(os.path.join(glider_dir, "health"), exist_ok=True)
        tmp = os.path.join(glider_dir, "health", ".vehicle.toml.tmp")
        with open(vehicle) as src, open(tmp, "w") as dst:
            dst.write(src.read())
        os.rename(tmp, os.path.join(glider_dir, "health", "vehicle.toml"))
    effects, alerts = [], []
    if drag_ratio is not None:
        series = []
        for k in range(8):  # a week of daily estimates rising from 1.0 to drag_ratio
            v = 1.0 + (drag_ratio - 1.0) * k / 7.0
            series.append({"t_utc": utc(-86400 * (7 - k)), "value": round(v, 4),
                           "lo": round(v - 0.03, 4), "hi": round(v + 0.03, 4)})
        effects.append({"name": "drag_change", "unit": "ratio", "shape": "line", "value": drag_ratio,
                        "ci95": [round(drag_ratio - 0.03, 3), round(drag_ratio + 0.03, 3)],
                        "since_utc": utc(-86400 * 7), "threshold": {"size": 0.05, "test": "p < 0.01 (fixture)"},
                        "series": series})
        if state == "alert":
            alerts.append({"id": "drag_change@" + series[0]["t_utc"], "effect": "drag_change",
                           "size": round(drag_ratio - 1.0, 3), "ci95": effects[0]["ci95"],
                           "since_utc": series[0]["t_utc"],
                           "message": "drag up %d %% since %s: fouling?" % (round(100 * (drag_ratio - 1)),
                                                                          series[0]["t_utc"][:10]),
                           "check": "hull and sensors for fouling at the next recovery"})
    _write(os.path.join(glider_dir, "health", "health.json"),
           {"schema": "glider-health/1", "glider": glider, "updated_utc": utc(), "state": state,
            "segments": [], "effects": effects, "alerts": alerts, "fixture": "tests/console/fixture_reports.py"})


def write_forecast(glider_dir, glider, fix, lat, lon, in_s=7200.0, abort_risk=0.02):
    """The next surfacing at (lat, lon) in_s seconds from now, a 95 % ellipse of 900 x 400 m."""
    _write(os.path.join(glider_dir, "forecast", "forecast.json"),
           {"schema": "glider-forecast/1", "glider": glider, "made_utc": utc(),
            "from_fix": {"lat_deg": fix[0], "lon_deg": fix[1], "utc": utc()},
            "next_surfacing": {"lat_deg": lat, "lon_deg": lon, "time_utc": utc(in_s),
                               "time_p10_utc": utc(in_s - 600), "time_p90_utc": utc(in_s + 900),
                               "ellipse": {"level": 0.95, "semi_major_m": 900.0, "semi_minor_m": 400.0,
                                           "orientation_deg": 30.0}},
            "abort_risk": abort_risk, "abort_causes": {"MS_ABORT_OVERDEPTH": abort_risk} if abort_risk else {},
            "baseline": {"lat_deg": lat + 0.002, "lon_deg": lon, "what": "last depth-averaged current persists"},
            "runs": 200, "mission": "box.mi", "queued_applied": [], "notes": ["fixture"],
            "fixture": "tests/console/fixture_reports.py"})
