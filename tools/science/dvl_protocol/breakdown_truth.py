#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The DVL protocol's breakdown on the independent truth: glider-truth flies
logs with a clean DVL (the true speed plus white noise of 0.5-2 cm/s), a
third with a hidden vertical effect, and glider-dvl-protocol scores both
models on them. Printed per log and in sum: the held-out ratio
glider-diagnose / gliderflight, and how much of each model's squared error
falls where the DVL and the measured depth rate imply an angle of attack
below 1 deg, and its concentration there (share of the squared error /
share of the samples: 1 where those samples are no worse than the rest). On
a clean DVL those samples are noise in the speed and the depth rate; the
real log's concentration (docs/science.md) is read against these. Fresh seeds each run (printed;
--seed S replays the run, --draw-seed D one log of it). A log on which gliderflight's dynamic fit diverges
has no score and is skipped; the run is judged on the logs that converge and reports SKIPPED (77) only
when too few do to judge (gliderflight diverges on about 1 log in 8).

The CTest's judgement (--max-concentration 2.5 --max-logs-above 1, 4 logs): fails only where two
converged logs or more exceed 2.5 - a concentration every log shares, as a model error at small angles
of attack would be - not on one log alone. Measured (session 41, 122 clean truth logs; fresh run seeds
2012366483 (40 logs), 30202575 (80) and 20 CTest runs): 0.64-2.00 but one, 2.75 (draw 667823378: 24 of
244 samples below 1 deg, a share that few samples make noisy). One log in 122 above 2.5 failed the rule
before (any log above: 1 in 20 CTest runs); two of four above is about 6 p^2 = 4e-4 a run at p = 1/122
(1 % at p's 95 % upper bound 0.045). Fewer than max-logs-above + 1 converged logs judge nothing: SKIPPED.

  tools/science/dvl_protocol/breakdown_truth.py --build build/release --logs 6
"""
import argparse
import os
import random
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
EFFECTS = [None, None, "buoyancy_offset", "drag_change", "hull_compressibility"]


def one_log(build, draw_seed, workdir):
    rng = random.Random(draw_seed)
    truth_seed = rng.randrange(1, 2**31)
    yos = rng.randint(6, 10)
    noise = rng.uniform(0.005, 0.02)
    effect = rng.choice(EFFECTS)
    extra = []
    if effect is not None:
        value = {"buoyancy_offset": rng.choice([-1, 1]) * rng.uniform(0.010, 0.060),
                 "drag_change": rng.uniform(1.08, 1.4),
                 "hull_compressibility": rng.uniform(0.5e-10, 3e-10)}[effect]
        extra = ["--effect", f"{effect}={value:.6g}"]
    csv = os.path.join(workdir, f"truth_{draw_seed}.csv")
    subprocess.run([os.path.join(build, "tools/science/truth/glider-truth"), "--seed", str(truth_seed), "--yos",
                    str(yos), "--dvl-noise", f"{noise:.4f}", "--out", csv] + extra,
                   check=True, capture_output=True, text=True)
    run = subprocess.run([os.path.join(build, "tools/science/dvl_protocol/glider-dvl-protocol"), csv, "--vehicle",
                          os.path.join(ROOT, "boards/vehicles/slocum_shallow.toml")], capture_output=True, text=True)
    os.remove(csv)
    if run.returncode != 0:
        return {"draw_seed": draw_seed, "error": run.stderr.strip().splitlines()[-1:]}
    out = run.stdout
    if re.search(r"\| gliderflight dynamic \([^|]*\) \| nan \|", out):
        # Its calibration can settle where the dynamic model diverges on some records (their NaN dropped from the
        # mean, as gliderflight's np.nanmean does): no held-out score to compare with.
        return {"draw_seed": draw_seed, "skipped": "gliderflight dynamic has no held-out score (its fit diverged)"}
    ratio = re.search(r"held-out ratio glider-diagnose / gliderflight dynamic: ([0-9.]+) every yo, ([0-9.]+)", out)
    low = re.search(r"\| measured alpha < 1 deg \| (\d+) \| [-+0-9.]+ / [-+0-9.]+ / ([0-9.]+) \| "
                    r"[-+0-9.]+ / [-+0-9.]+ / ([0-9.]+) \|", out)
    total = re.search(r"\| all \| (\d+) \|", out)
    return {"draw_seed": draw_seed, "noise": noise, "effect": " ".join(extra) or "none",
            "ratio": float(ratio.group(1)), "ratio_kept": float(ratio.group(2)),
            "low_samples": int(low.group(1)) if low else 0, "samples": int(total.group(1)) if total else 0,
            "low_share": (float(low.group(2)), float(low.group(3))) if low else (0.0, 0.0)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.path.join(ROOT, "build/release"))
    ap.add_argument("--logs", type=int, default=6)
    ap.add_argument("--seed", type=int, default=None, help="replay a run (default: fresh, printed)")
    ap.add_argument("--draw-seed", type=int, default=None, help="replay one log (its draw seed, as printed)")
    ap.add_argument("--max-concentration", type=float, default=None,
                    help="exit 1 if a log's concentration exceeds this (the CTest's check: on a clean DVL the "
                         "samples below 1 deg are no worse than the rest, as noise)")
    ap.add_argument("--max-logs-above", type=int, default=0,
                    help="with --max-concentration: exit 1 only if more logs than this exceed it (a shared "
                         "concentration, not one log's noise); fewer converged logs than this + 1 judge "
                         "nothing (SKIPPED, 77)")
    args = ap.parse_args()
    if args.logs < 1:
        print("breakdown_truth.py: --logs must be >= 1", file=sys.stderr)
        return 2
    seed = args.seed if args.seed is not None else random.SystemRandom().randrange(1, 2**31)
    print(f"seed {seed} (--seed {seed} --logs {args.logs} replays it)")
    rng = random.Random(seed)
    results = []
    with tempfile.TemporaryDirectory() as workdir:
        draws = [args.draw_seed] if args.draw_seed is not None else [rng.randrange(1, 2**31) for _ in range(args.logs)]
        for draw in draws:
            r = one_log(args.build, draw, workdir)
            results.append(r)
            if "error" in r:
                print(f"draw {r['draw_seed']}: failed: {r['error']}")
                continue
            if "skipped" in r:
                print(f"draw {r['draw_seed']}: skipped: {r['skipped']}")
                continue
            print(f"draw {r['draw_seed']}: DVL noise {100 * r['noise']:.2f} cm/s, effect {r['effect']}: ratio "
                  f"{r['ratio']:.3f} (without excluded {r['ratio_kept']:.3f}); implied alpha < 1 deg: "
                  f"{r['low_samples']}/{r['samples']} samples, {r['low_share'][0]:.2f} / {r['low_share'][1]:.2f} "
                  f"of the squared error (glider-diagnose / gliderflight)"
                  f", concentration {max(r['low_share']) / max(r['low_samples'] / max(r['samples'], 1), 1e-9):.2f}")
    ok = [r for r in results if "error" not in r and "skipped" not in r]
    failed = sum("error" in r for r in results)
    if not ok:
        return 1 if failed else 77  # every log skipped: nothing judged (CTest SKIP)
    frac = sorted(r["low_samples"] / max(r["samples"], 1) for r in ok)
    conc = sorted(max(r["low_share"]) / max(r["low_samples"] / max(r["samples"], 1), 1e-9) for r in ok)
    share = sorted(max(r["low_share"]) for r in ok)
    ratios = sorted(r["ratio_kept"] for r in ok)
    print(f"{len(ok)} logs ({failed} failed, {len(results) - len(ok) - failed} skipped): samples with implied alpha < 1 deg "
          f"{frac[0]:.2f}-{frac[-1]:.2f}; their share of either model's squared error at most {share[-1]:.2f} "
          f"(median {share[len(share) // 2]:.2f}), concentration (share / fraction of samples) {conc[0]:.2f}-{conc[-1]:.2f}; "
          f"held-out ratio {ratios[0]:.3f}-{ratios[-1]:.3f} "
          f"(median {ratios[len(ratios) // 2]:.3f})")
    if args.max_concentration is not None:
        if len(ok) <= args.max_logs_above:
            print(f"SKIPPED: {len(ok)} converged logs judge nothing (more than {args.max_logs_above} above "
                  f"{args.max_concentration} needed to fail)")
            return 1 if failed else 77
        above = [c for c in conc if c > args.max_concentration]
        if len(above) > args.max_logs_above:
            print(f"FAIL: concentration above {args.max_concentration} on {len(above)} of {len(ok)} logs "
                  f"({', '.join(f'{c:.2f}' for c in above)}; at most {args.max_logs_above} allowed)")
            return 1
        if above:
            print(f"NOTE: concentration above {args.max_concentration} on {len(above)} of {len(ok)} logs "
                  f"({', '.join(f'{c:.2f}' for c in above)}): not shared, at most {args.max_logs_above} allowed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
