#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""What a segment's fin motion is made of (docs/health.md, "comet-2019: fin 0.60
against 1.93"): per CSV log (tests/data/real/*.csv, one row per cycle), the fin's
mean on dives and climbs, its spread within a glide against its whole spread,
the logged roll, the commanded and flown headings' spreads, and a least-squares
fit of the yaw rate (from the unwrapped m_heading) on the fin and a dive/climb
sign - the signature of a roll offset's yaw, which reverses with the glide. A
fin whose motion is mostly that sign cannot be told from a roll offset: the
correlation of the two estimates says how much. No model, no vehicle file.

    /usr/bin/python3 benchmarks/bench_health_fin_ridge.py tests/data/real/comet-2019-222-02-15[46].csv
"""
import csv
import math
import sys

import numpy as np

DEG = 180.0 / math.pi


def load(path):
    with open(path) as f:
        rows = csv.reader(line for line in f if not line.startswith("#"))
        names = next(rows)
        cols = {n: [] for n in names}
        for row in rows:
            for n, v in zip(names, row):
                cols[n].append(float(v) if v != "" else np.nan)
    return {n: np.array(v) for n, v in cols.items()}


def held(a):
    a = a.copy()
    for i in range(1, len(a)):
        if np.isnan(a[i]):
            a[i] = a[i - 1]
    return a


def circular_sd_deg(a):
    a = a[np.isfinite(a)]
    r = math.hypot(np.mean(np.cos(a)), np.mean(np.sin(a)))
    return math.sqrt(-2.0 * math.log(r)) * DEG


def report(path):
    d = load(path)
    t = d["m_present_time"]
    z, fin, heading = held(d["m_depth"]), held(d["m_fin"]), held(d["m_heading"])
    command, roll = held(d["c_heading"]), held(d["m_roll"])
    rate_z = np.gradient(z, t)
    under = z > 2.0
    dive, climb = under & (rate_z > 0.05), under & (rate_z < -0.05)
    sign = np.where(dive, 1.0, np.where(climb, -1.0, 0.0))
    yaw = np.gradient(np.unwrap(heading), t)
    m = (dive | climb) & np.isfinite(yaw) & np.isfinite(fin)
    glide = np.cumsum(np.r_[0, np.diff(sign) != 0])
    print(path.split("/")[-1])
    print("  depth to %.1f m, %d dives; roll %.2f deg (sd %.2f)" % (np.nanmax(z), np.sum(np.diff(dive.astype(int)) == 1),
                                                                 np.nanmean(roll[under]) * DEG, np.nanstd(roll[under]) * DEG))
    print("  heading spread under water: flown %.1f deg, commanded %.1f deg" % (circular_sd_deg(heading[under]),
                                                                               circular_sd_deg(command[under])))
    for name, k in (("dives", dive), ("climbs", climb)):
        off = np.nanmean((command[k] - heading[k] + math.pi) % (2 * math.pi) - math.pi) * DEG
        print("  %-6s fin %+.2f deg (sd %.2f), heading %+.1f deg off the command" % (name, np.nanmean(fin[k]) * DEG,
                                                                                  np.nanstd(fin[k]) * DEG, off))
    x = np.column_stack([fin[m], sign[m]])
    b, _, _, _ = np.linalg.lstsq(x, yaw[m], rcond=None)
    cov = np.linalg.inv(x.T @ x) * np.var(yaw[m] - x @ b)
    within_fin, within_yaw = fin.copy(), yaw.copy()
    for g in np.unique(glide[m]):
        k = m & (glide == g)
        within_fin[k] -= fin[k].mean()
        within_yaw[k] -= yaw[k].mean()
    print("  fin spread %.2f deg, within a glide %.2f deg; fin vs dive/climb sign correlation %+.2f" % (
        np.std(fin[m]) * DEG, np.std(within_fin[m]) * DEG, np.corrcoef(fin[m], sign[m])[0, 1]))
    print("  yaw rate ~ fin + sign: fin %.4f 1/s, sign %+.3f deg/s, estimates' correlation %+.2f; within glides: "
          "fin %.4f 1/s" % (b[0], b[1] * DEG, cov[0, 1] / math.sqrt(cov[0, 0] * cov[1, 1]),
                            np.sum(within_fin[m] * within_yaw[m]) / np.sum(within_fin[m] ** 2)))


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for p in sys.argv[1:]:
        report(p)
