#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""forecast.fit_tide: `glider-forecast fit-tide` on a SIL truth's own depth-averaged currents (docs/forecast.md,
session 44). An nsb3.mi truth (3 h dives) of a fresh seed (printed; a 4th argument replays it) flown for 10
surfacings (27 h: M2 resolvable), its glider folder fitted for M2, the fitted tidal current against the truth's
over one period: the vector RMS difference under 0.015 m/s (0.000-0.002 in 8 fresh seeds: the SIL's 3 m fixes over
3 h dives; a 20 deg phase error of a 0.1 m/s tide is 0.025). Then the same folder cut to 4 surfacings (3 estimates,
9 h) must be refused.
Usage: check_fit_tide.py BENCH FORECAST SOURCE_DIR OUT_DIR [SEED]"""
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tomllib

M2_S = 12.4206012 * 3600.0


def main():
    bench, forecast, source, out = sys.argv[1:5]
    seed = int(sys.argv[5]) if len(sys.argv) > 5 else random.SystemRandom().randrange(1, 1000000)
    print("seed %d (check_fit_tide.py ... %d replays it)" % (seed, seed))
    shutil.rmtree(out, ignore_errors=True)
    run = subprocess.run([bench, "--seed", str(seed), "--threads", "1", "--mission",
                          os.path.join(source, "boards/missions/comet-nsb3/missions/nsb3.mi"), "--vehicle",
                          os.path.join(source, "boards/vehicles/slocum_comet.toml"), "--truths", "1",
                          "--surfacings", "10", "--from", "9", "--runs", "2", "--out", out],
                         capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        print("FAIL fit_tide: the bench failed")
        return 1
    m = re.search(r"M2 tide ([0-9.]+) m/s toward ([0-9.-]+) deg \(phase ([0-9.-]+) deg\)", run.stdout)
    print(run.stdout.splitlines()[0])
    amplitude, toward, phase = (float(v) for v in m.groups())
    folder = os.path.join(out, "seed%d" % seed, "from9")
    table = os.path.join(out, "tide.toml")
    fit = subprocess.run([forecast, "fit-tide", "--glider-dir", folder, "--out", table], capture_output=True,
                         text=True)
    print(fit.stderr.strip())
    if fit.returncode != 0:
        print("FAIL fit_tide: fit-tide refused the 27 h record")
        return 1
    with open(table, "rb") as f:
        t = tomllib.load(f)
    m2 = t["M2"]
    # The truth: amplitude x sin(omega t + phase) along `toward`, t from the launch (the table's reference).
    worst, sum2, n = 0.0, 0.0, 48
    for i in range(n):
        x = 2.0 * math.pi * i / n
        true_e = amplitude * math.sin(math.radians(toward)) * math.sin(x + math.radians(phase))
        true_n = amplitude * math.cos(math.radians(toward)) * math.sin(x + math.radians(phase))
        fit_e = m2["east_amplitude_m_s"] * math.cos(x - math.radians(m2["east_phase_deg"]))
        fit_n = m2["north_amplitude_m_s"] * math.cos(x - math.radians(m2["north_phase_deg"]))
        d = math.hypot(fit_e - true_e, fit_n - true_n)
        sum2 += d * d
        worst = max(worst, d)
    rms = math.sqrt(sum2 / n)
    print("fitted M2 against the truth's over a period: RMS %.3f m/s, worst %.3f m/s" % (rms, worst))
    failures = []
    if not rms < 0.015:
        failures.append("the fitted M2 is %.3f m/s RMS off the truth's (0.015 allowed)" % rms)
    # Too short: the first 4 events only (3 estimates over ~9 h) are refused.
    short = os.path.join(out, "short")
    shutil.copytree(folder, short)
    for name in sorted(os.listdir(os.path.join(short, "logs")))[4:]:
        os.remove(os.path.join(short, "logs", name))
    refused = subprocess.run([forecast, "fit-tide", "--glider-dir", short], capture_output=True, text=True)
    print(refused.stderr.strip())
    if refused.returncode != 1 or "too short to fit M2" not in refused.stderr:
        failures.append("a 4-event record was not refused (exit %d)" % refused.returncode)
    print("FAIL fit_tide: " + "; ".join(failures) if failures else "PASS fit_tide")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
