#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Where each real forecast's position error comes from: current, flight (speed, heading), timing (docs/forecast.md).

For every scored surfacing pair of benchmarks/forecast_real.py (comet-2019's two, comet-2016's five; the same
glider-forecast and options) the error is split exactly, by what the water does and does not change. The forecast's
firmware steers and dead-reckons with what the glider believed (its m_water_vx/vy at the dive), never with the
water: so the water only displaces the track, and a forecast flown in another uniform current c is the same runs
moved by (c - its current) x time. The split (vectors east, north m from the fix the glider dived from):
  current  = (forecast current - true current) x forecast dive: what the current estimate explains;
             true current: comet-2019 the glider's next update (its 3 h dives' DR is not reset: the update is
             the dive's mean by construction), comet-2016 the current the fixes say (its updates lag: the DR
             reset at the yo tops);
  timing   = the forecast's ground velocity in the true current x (forecast dive - true dive);
  speed    = the rest along the glider's own through-water track (its DR less the believed current x time):
             the model's speed through the water;
  heading  = the rest across that track (the autopilot, the waypoint, the compass);
  own      = the true current's own residual (truth - DR end - (true - believed current) x true dive: 0 when
             the true current is the glider's update over the same DR).
They add up to the error. The identity is checked by flying the forecast again with --current-prior off
(persistence of the believed current) and comparing it with the as-is runs moved by (believed - forecast) x time.
With --check (CTest forecast.real_attribution) exits 1 unless the terms add up to each error within 1 m and the
diagnosis of the p90's forecast holds: comet-2019 from surfacing 0, the current term at least 90 % of the error's
length and the error with the true current within 0.5 km (the issue's median goal).
Usage: forecast_attribution.py --build BUILD_DIR [--deployment comet-2019|comet-2016|all (default all)] [--check]
       [forecast_real.py's forecast options: --runs N --from-glider ...]
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import forecast_real as fr  # noqa: E402  (the benchmark's cases and scoring, one way to read the logs)


def norm(v):
    return math.hypot(v[0], v[1])


def split(r, true_current):
    """The terms of one forecast's error (east, north m; the speed and heading terms signed m); they add up."""
    tp, tt = r["forecast_dive_s"], r["true_dive_s"]
    cp, cb, ct = r["current"], r["persistence"], true_current
    current = [(cp[i] - ct[i]) * tp for i in range(2)]
    model_water = [r["forecast_en"][i] - cp[i] * tp for i in range(2)]  # the model's track through the water
    glider_water = [r["dr_end_en"][i] - cb[i] * tt for i in range(2)]  # the glider's, by its own DR
    timing = [(model_water[i] / tp + ct[i]) * (tp - tt) for i in range(2)]
    flight = [model_water[i] * tt / tp - glider_water[i] for i in range(2)]
    own = [r["dr_end_en"][i] + (ct[i] - cb[i]) * tt - r["truth_en"][i] for i in range(2)]
    u = [glider_water[i] / norm(glider_water) for i in range(2)]
    return {"current": current, "timing": timing, "flight": flight, "own": own,
            "speed": flight[0] * u[0] + flight[1] * u[1], "heading": flight[1] * u[0] - flight[0] * u[1],
            "glider_water_m": norm(glider_water), "model_water_m": norm(model_water) * tt / tp,
            "sum": [current[i] + timing[i] + flight[i] + own[i] for i in range(2)]}


def main():
    p = fr.arguments(__doc__.splitlines()[0])
    p.set_defaults(deployment="all")
    a = p.parse_args()
    out = a.out or os.path.join(a.build, "benchmark", "forecast_attribution")
    real = os.path.join(a.source, "tests", "data", "real")
    vehicle = os.path.join(a.source, "boards", "vehicles", "slocum_comet.toml")
    forecast = fr.find_program(a.build, "glider-forecast")
    fr.tempdir = os.path.join(out, "dbd")
    os.makedirs(fr.tempdir, exist_ok=True)
    convert = fr.find_program(a.build, "glider-convert")
    cases = []
    if a.deployment in ("comet-2019", "all"):
        cases += [(c, (c["truth"]["water"]["m_water_vx"], c["truth"]["water"]["m_water_vy"]), "next update")
                  for c in fr.comet_2019_cases(a, real, convert)]
    if a.deployment in ("comet-2016", "all"):
        cases += [(c, c["truth"]["fix_current"], "the fixes") for c in fr.comet_2016_cases(a, real, convert)
                  if not c["timer"]]
    rows = []
    for case, true_current, source in cases:
        r = fr.run_case(a, forecast, vehicle, out, case)
        b = argparse.Namespace(**vars(a))
        b.current_prior = "off"
        c = dict(case, dir=case["dir"] + "_persistence")
        p = fr.run_case(b, forecast, vehicle, out, c)
        # the identity: the as-is runs moved by (believed - forecast current) x time against the persistence runs
        moved = [r["forecast_en"][i] + (r["persistence"][i] - r["current"][i]) * r["forecast_dive_s"] for i in range(2)]
        check = norm([moved[i] - p["forecast_en"][i] for i in range(2)])
        rows.append((case, r, split(r, true_current), true_current, source, check))
    print("\n| forecast from | error | current | timing (dive forecast / true) | speed: along (through water: "
          "model / glider) | heading: across | own | with the true current | identity check |")
    print("|---|---|---|---|---|---|---|---|---|")
    failures = []
    for case, r, s, tc, source, check in rows:
        name = ("comet-2019" if not case["label"] else case["label"].strip()) + " %d" % case["k"]
        rest = [s["sum"][i] - s["current"][i] for i in range(2)]
        if not norm([s["sum"][i] - r["error_en"][i] for i in range(2)]) <= 1.0:
            failures.append("%s: the terms do not add up to the error" % name)
        if not case["label"] and case["k"] == 0:
            if not norm(s["current"]) >= 0.9 * r["pos"]:
                failures.append("%s: the current term %.0f m is under 90 %% of the error %.0f m" %
                                (name, norm(s["current"]), r["pos"]))
            if not norm(rest) <= 500.0:
                failures.append("%s: with the true current %.0f m off (500 allowed)" % (name, norm(rest)))
        print("| %s | %.2f km | %.2f km (%+.0f E %+.0f N) | %.2f km (%.0f / %.0f s) | %+.2f km (%.2f / %.2f km) "
              "| %+.2f km | %.2f km | %.2f km | %.0f m |" %
              (name, r["pos"] / 1000, norm(s["current"]) / 1000, s["current"][0], s["current"][1],
               norm(s["timing"]) / 1000, r["forecast_dive_s"], r["true_dive_s"], s["speed"] / 1000,
               s["model_water_m"] / 1000, s["glider_water_m"] / 1000, s["heading"] / 1000, norm(s["own"]) / 1000,
               norm(rest) / 1000, check))
    print("\n| forecast from | current: forecast / believed (persistence) / true (E, N m/s) |\n|---|---|")
    for case, r, s, tc, source, check in rows:
        name = ("comet-2019" if not case["label"] else case["label"].strip()) + " %d" % case["k"]
        print("| %s | %+.3f %+.3f / %+.3f %+.3f / %+.3f %+.3f (%s) |" %
              (name, r["current"][0], r["current"][1], r["persistence"][0], r["persistence"][1], tc[0], tc[1], source))
    pos = [r["pos"] for _, r, _, _, _, _ in rows]
    tru = [norm([s["sum"][i] - s["current"][i] for i in range(2)]) for _, _, s, _, _, _ in rows]
    print("\nall %d: as is median / p90 %.2f / %.2f km; with the true current %.2f / %.2f km" %
          (len(rows), fr.median(pos) / 1000, fr.p90(pos) / 1000, fr.median(tru) / 1000, fr.p90(tru) / 1000))
    keep = [i for i, row in enumerate(rows) if row[0]["k"] > 0]
    print("without each deployment's surfacing 0 (%d): as is %.2f / %.2f km; with the true current %.2f / %.2f km" %
          (len(keep), fr.median([pos[i] for i in keep]) / 1000, fr.p90([pos[i] for i in keep]) / 1000,
           fr.median([tru[i] for i in keep]) / 1000, fr.p90([tru[i] for i in keep]) / 1000))
    if a.check:
        print("FAIL real_attribution: " + "; ".join(failures) if failures else "PASS real_attribution")
        sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
