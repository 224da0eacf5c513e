#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Live cross-check of the C++ seawater chain against python3-gsw.

Draws a seeded random set of CTD samples (C, t, p), runs them through
seawater_probe (the C++ code) and through gsw, and fails if any quantity
differs by more than its tolerance, or if the C++ code says NaN where the
point is inside its documented range (or a number where it is outside).
Prints the worst case of each quantity.

Usage: check_seawater_vs_gsw.py PATH/TO/seawater_probe [--points N] [--seed S]
Exit: 0 pass, 1 fail, 77 python3-gsw not installed (CTest: skipped).
"""
import argparse
import subprocess
import sys

try:
    import gsw
    import numpy as np
except ImportError as e:  # pragma: no cover - depends on the machine
    print(f"check_seawater_vs_gsw: skipped, {e} (apt-get install python3-gsw)")
    sys.exit(77)

from make_seawater_reference import in_funnel  # the one statement of seawater.hpp's density range

# Same algorithms and coefficients as GSW-C: differences are rounding.
# C is the inverse of PSS-78 (gsw.C_from_SP, mS/cm there): GSW stops its
# modified Newton iteration after a fixed number of steps, the C++ code when
# the step reaches rounding, so the two agree to a few 1e-12 S/m, not bits.
TOLERANCES = {"SP": 1e-10, "SA": 1e-10, "CT": 1e-10, "rho": 1e-6, "C": 1e-10}
UNITS = {"SP": "", "SA": " g/kg", "CT": " degC", "rho": " kg/m^3", "C": " S/m"}


def draw(rng, n):
    """n liquid CTD samples: mostly glider depths, some to 10000 dbar."""
    sp, t, p = [], [], []
    while len(sp) < n:
        m = 2 * n
        s = np.where(rng.random(m) < 0.15, rng.uniform(0.0, 2.0, m), rng.uniform(2.0, 41.9, m))
        tt = rng.uniform(-3.0, 40.0, m)
        pp = np.where(rng.random(m) < 0.6, rng.uniform(0.0, 1000.0, m), rng.uniform(0.0, 10000.0, m))
        liquid = tt >= gsw.t_freezing(gsw.SR_from_SP(s), pp, 0.0)
        sp.extend(s[liquid]), t.extend(tt[liquid]), p.extend(pp[liquid])
    sp, t, p = (np.array(a[:n]) for a in (sp, t, p))
    return gsw.C_from_SP(sp, t, p) / 10.0, t, p  # C in S/m, as the C++ side takes it


def run_probe(probe, c, t, p):
    lines = "".join(f"{a:.17g} {b:.17g} {d:.17g}\n" for a, b, d in zip(c, t, p))
    out = subprocess.run([probe], input=lines, capture_output=True, text=True, check=True).stdout
    values = np.array([[float(x) for x in line.split()] for line in out.splitlines()])
    if values.shape != (len(c), 5):
        sys.exit(f"check_seawater_vs_gsw: probe printed {values.shape}, expected {(len(c), 5)}")
    return dict(zip(("SP", "SA", "CT", "rho", "C"), values.T))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("probe")
    parser.add_argument("--points", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=20240611)
    args = parser.parse_args()

    c, t, p = draw(np.random.default_rng(args.seed), args.points)
    ours = run_probe(args.probe, c, t, p)
    sp = gsw.SP_from_C(c * 10.0, t, p)
    sa = gsw.SR_from_SP(sp)
    ct = gsw.CT_from_t(sa, t, p)
    # C back from gsw's own SP (the probe inverts its SP, equal to rounding).
    ref = {"SP": sp, "SA": sa, "CT": ct, "rho": gsw.rho(sa, ct, p), "C": gsw.C_from_SP(sp, t, p) / 10.0}
    # SP and SA are defined for every drawn point (SP < 42), CT for SA <= 42 g/kg
    # (SP <= 41.8), density only inside the funnel.
    everywhere = np.ones(len(c), bool)
    expect_value = {"SP": everywhere, "SA": everywhere, "CT": sa <= 42.0, "rho": in_funnel(sa, ct, p),
                    "C": everywhere}

    failed = False
    print(f"seawater_probe vs python3-gsw {gsw.__version__}: {len(c)} points (seed {args.seed}), "
          f"{int(expect_value['CT'].sum())} with SA <= 42 g/kg, {int(expect_value['rho'].sum())} inside the density "
          "range")
    for name, tol in TOLERANCES.items():
        want = expect_value[name]
        wrong_nan = np.flatnonzero(np.isnan(ours[name]) != ~want)
        if wrong_nan.size:
            i = wrong_nan[0]
            print(f"  FAIL {name}: {wrong_nan.size} points NaN where they should not be (or the reverse), e.g. "
                  f"C={c[i]:.6f} S/m t={t[i]:.4f} degC p={p[i]:.2f} dbar: ours {ours[name][i]!r}, gsw {ref[name][i]!r}")
            failed = True
        diff = np.where(want, np.abs(ours[name] - ref[name]), 0.0)
        diff = np.where(np.isnan(diff), np.inf, diff)
        i = int(np.argmax(diff))
        status = "ok  " if diff[i] <= tol else "FAIL"
        failed |= diff[i] > tol
        if diff[i] == 0.0:
            print(f"  {status} {name:3s} identical to gsw, bit for bit, on all {int(want.sum())} points")
            continue
        print(f"  {status} {name:3s} worst |diff| {diff[i]:.3g}{UNITS[name]} (tolerance {tol:g}) at "
              f"C={c[i]:.6f} S/m t={t[i]:.4f} degC p={p[i]:.2f} dbar: ours {ours[name][i]!r}, gsw {ref[name][i]!r}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
