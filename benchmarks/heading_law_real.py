#!/usr/bin/env python3
"""Which current-correction law does a real Slocum fly? Both laws against its logged c_heading.

For every real deployment under tests/data/real/dbd whose .dbd files log the commanded heading (c_heading), the
active waypoint (c_wpt_lat/lon), the dead-reckoned position (m_lat/m_lon) and the depth-averaged current estimate
(m_water_vx/vy, with m_avg_speed and m_speed), this predicts c_heading at each cycle that logged it with

  aim    Slocum's goto law (as glidersim, github.com/smerckel/glidersim glidersim/glidersim.py resolveWpt, emulates
         it): steer at the waypoint moved upstream by the current times the time to get there,
         aim = waypoint - (m_water_vx, m_water_vy) * distance / max(0.1 m/s, U)
  crab   this firmware's law before the navigator change: bearing + clamp(-asin(c_perp / U), +-60 deg), c_perp the
         current's component to the right of the bearing (the bearing itself when U <= 0.05 m/s)
  none   the bearing to the waypoint, no correction

each with U = m_avg_speed (the glider's running mean speed) and U = m_speed (its instantaneous one), and prints the
median and 90th percentile of |predicted - c_heading| per deployment: over all usable cycles, over those at least
500 m from the waypoint, and over those also below 2 m depth. Values the .dbd logs only when they change (c_wpt_*,
m_water_v*, x_last_wpt_*) are carried forward; before the first c_wpt of a deployment the waypoint is the one its
first x_last_wpt names (the waypoint just reached). The waypoint is checked against the glider's own m_dist_to_wpt.

Usage: benchmarks/heading_law_real.py --build BUILD_DIR [--source REPO] [--check]
--check exits 1 unless, on every deployment that corrects for the current, the aim law's median error (m_avg_speed,
all cycles) is below 2 deg and below the crab law's.
"""
import argparse
import csv
import math
import os
import subprocess
import sys
import tempfile

COLUMNS = ("c_heading,c_wpt_x_lmc,c_wpt_y_lmc,c_wpt_lat,c_wpt_lon,x_last_wpt_lat,x_last_wpt_lon,m_x_lmc,m_y_lmc,"
           "m_lat,m_lon,m_water_vx,m_water_vy,m_avg_speed,m_speed,m_depth,m_dist_to_wpt,u_use_current_correction")
CARRIED = ("c_wpt_x_lmc", "c_wpt_y_lmc", "m_water_vx", "m_water_vy", "m_avg_speed", "m_speed", "m_depth",
           "u_use_current_correction")
MAX_CRAB = 1.05  # rad, the firmware's cap before the change (kMaxCrabRad)


def ddmm(v):
    sign = -1.0 if v < 0 else 1.0
    v = abs(v)
    deg = math.floor(v / 100.0)
    return sign * (deg + (v - 100.0 * deg) / 60.0)


def find_program(build, name):
    for root, _, files in os.walk(os.path.join(build, "tools")):
        if name in files:
            return os.path.join(root, name)
    raise SystemExit("%s not built in %s (cmake --build %s --target %s)" % (name, build, build, name))


def load(convert, folder):
    with tempfile.TemporaryDirectory() as tmp:
        out = os.path.join(tmp, "log.csv")
        subprocess.run([convert, folder, "--quiet", "--out", out, "--columns", COLUMNS], check=True,
                       capture_output=True)
        with open(out) as f:
            reader = csv.DictReader(line for line in f if not line.startswith("#"))
            return [{k: float(v) for k, v in r.items() if v != ""} for r in reader]


def solve3(m, v):
    """Gaussian elimination for a 3x3 system (no numpy: the script needs only the Python standard library)."""
    m = [row[:] + [x] for row, x in zip(m, v)]
    for i in range(3):
        k = max(range(i, 3), key=lambda j: abs(m[j][i]))
        m[i], m[k] = m[k], m[i]
        for j in range(i + 1, 3):
            f = m[j][i] / m[i][i]
            m[j] = [x - f * y for x, y in zip(m[j], m[i])]
    out = [0.0] * 3
    for i in (2, 1, 0):
        out[i] = (m[i][3] - sum(m[i][j] * out[j] for j in range(i + 1, 3))) / m[i][i]
    return out


def lmc_fit(rows):
    """Affine map (lat, lon) -> LMC (x, y) fitted on the glider's own m_lat/m_lon against m_x_lmc/m_y_lmc (it
    derives one from the other): places a waypoint known only by lat/lon in the frame the glider steers in."""
    pts = [(ddmm(r["m_lat"]), ddmm(r["m_lon"]), r["m_x_lmc"], r["m_y_lmc"]) for r in rows
           if all(k in r for k in ("m_lat", "m_lon", "m_x_lmc", "m_y_lmc"))]
    lat0, lon0 = pts[0][0], pts[0][1]
    basis = [(1.0, p[0] - lat0, p[1] - lon0) for p in pts]
    normal = [[sum(b[i] * b[j] for b in basis) for j in range(3)] for i in range(3)]
    cx = solve3(normal, [sum(b[i] * p[2] for b, p in zip(basis, pts)) for i in range(3)])
    cy = solve3(normal, [sum(b[i] * p[3] for b, p in zip(basis, pts)) for i in range(3)])

    def to_lmc(lat_ddmm, lon_ddmm):
        b = (1.0, ddmm(lat_ddmm) - lat0, ddmm(lon_ddmm) - lon0)
        return sum(c * x for c, x in zip(cx, b)), sum(c * x for c, x in zip(cy, b))
    return to_lmc


def wrap(a):
    return (a + math.pi) % (2.0 * math.pi) - math.pi


def aim_law(de, dn, vx, vy, speed):
    t = math.hypot(de, dn) / max(0.1, speed)
    return math.atan2(de - vx * t, dn - vy * t)


def crab_law(de, dn, vx, vy, speed):
    bearing = math.atan2(de, dn)
    if not speed > 0.05:
        return bearing
    c_perp = vx * math.cos(bearing) - vy * math.sin(bearing)
    return bearing + max(-MAX_CRAB, min(MAX_CRAB, -math.asin(max(-1.0, min(1.0, c_perp / speed)))))


def samples(rows):
    """One sample per cycle that logged c_heading with a known position, waypoint, current and speeds, in the
    glider's LMC frame (x east, y north, m). Also the fit's residual on waypoints logged both ways."""
    to_lmc = lmc_fit(rows)
    fit_residual = [math.hypot(*(a - b for a, b in zip(to_lmc(r["c_wpt_lat"], r["c_wpt_lon"]),
                                                        (r["c_wpt_x_lmc"], r["c_wpt_y_lmc"]))))
                    for r in rows if all(k in r for k in ("c_wpt_lat", "c_wpt_lon", "c_wpt_x_lmc", "c_wpt_y_lmc"))
                    and r["c_wpt_lat"] != 0.0]
    first_reached = next(((r["x_last_wpt_lat"], r["x_last_wpt_lon"]) for r in rows
                          if "x_last_wpt_lat" in r and "x_last_wpt_lon" in r), None)
    state, out = {}, []
    if first_reached is not None:
        state["c_wpt_x_lmc"], state["c_wpt_y_lmc"] = to_lmc(*first_reached)
    for r in rows:
        for k in CARRIED:
            if k in r:
                state[k] = r[k]
        if r.get("c_wpt_lat") == 0.0:  # cleared (no waypoint): not a place to steer at
            state.pop("c_wpt_x_lmc", None)
            state.pop("c_wpt_y_lmc", None)
        if "c_heading" not in r or "m_x_lmc" not in r or "m_y_lmc" not in r:
            continue
        if not all(k in state for k in CARRIED[:6]):
            continue
        de, dn = state["c_wpt_x_lmc"] - r["m_x_lmc"], state["c_wpt_y_lmc"] - r["m_y_lmc"]
        out.append(dict(state, c_heading=r["c_heading"], de=de, dn=dn, dist=math.hypot(de, dn),
                        logged_dist=r.get("m_dist_to_wpt")))
    return out, fit_residual


def percentile(values, q):
    v = sorted(values)
    if not v:
        return float("nan")
    k = (len(v) - 1) * q
    lo = math.floor(k)
    hi = min(lo + 1, len(v) - 1)
    return v[lo] + (v[hi] - v[lo]) * (k - lo)


def errors(subset, law, speed_key):
    return [abs(math.degrees(wrap(law(s["de"], s["dn"], s["m_water_vx"], s["m_water_vy"], s[speed_key]) -
                                  s["c_heading"]))) for s in subset]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", required=True)
    p.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p.add_argument("--check", action="store_true")
    a = p.parse_args()
    convert = find_program(a.build, "glider-convert")
    root = os.path.join(a.source, "tests", "data", "real", "dbd")
    failures = []
    laws = (("aim", aim_law), ("crab", crab_law), ("none", lambda de, dn, vx, vy, u: math.atan2(de, dn)))
    for name in sorted(d for d in os.listdir(root) if os.path.isdir(os.path.join(root, d))):
        s, fit_residual = samples(load(convert, os.path.join(root, name)))
        if not s:
            print("%s: no cycle logs c_heading with a waypoint, position and current: skipped" % name)
            continue
        check = [abs(x["dist"] - x["logged_dist"]) for x in s if x.get("logged_dist") is not None]
        current = [math.hypot(x["m_water_vx"], x["m_water_vy"]) for x in s]
        correcting = {x.get("u_use_current_correction") for x in s}
        print("%s: lat/lon -> LMC fit residual on %d logged waypoints: max %.2f m" %
              (name, len(fit_residual), max(fit_residual) if fit_residual else float("nan")))
        print("%s: %d cycles; distance to waypoint vs m_dist_to_wpt: median %.1f m, max %.1f m; current %.2f-%.2f m/s;"
              " m_avg_speed median %.2f m/s; u_use_current_correction %s" %
              (name, len(s), percentile(check, 0.5), max(check) if check else float("nan"), min(current),
               max(current), percentile([x["m_avg_speed"] for x in s], 0.5),
               ",".join("%g" % c for c in sorted(c for c in correcting if c is not None)) or "not logged"))
        subsets = (("all", s), (">=500 m from wpt", [x for x in s if x["dist"] >= 500.0]),
                   (">=500 m, below 2 m", [x for x in s if x["dist"] >= 500.0 and x["m_depth"] > 2.0]))
        print("  %-20s %6s  %-26s %-26s %-26s" % ("cycles", "n", "aim law median/p90 deg", "crab law median/p90",
                                                   "no correction median/p90"))
        for speed_key in ("m_avg_speed", "m_speed"):
            for label, subset in subsets:
                cells = []
                for law_name, law in laws:
                    e = errors(subset, law, speed_key)
                    cells.append("%7.2f / %7.2f" % (percentile(e, 0.5), percentile(e, 0.9)))
                    if law_name == "aim" and speed_key == "m_avg_speed" and label == "all":
                        aim_median = percentile(e, 0.5)
                    if law_name == "crab" and speed_key == "m_avg_speed" and label == "all":
                        crab_median = percentile(e, 0.5)
                print("  %-20s %6d  %-26s %-26s %-26s" % ("%s, U=%s" % (label, speed_key), len(subset), *cells))
        if not (aim_median < 2.0 and aim_median < crab_median):
            failures.append("%s: aim law median %.2f deg, crab %.2f deg" % (name, aim_median, crab_median))
    if a.check and failures:
        print("FAIL: " + "; ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
