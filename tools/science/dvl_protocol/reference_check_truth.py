#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The DVL reference check (tools/science/diagnose speed_reference.hpp) validated on the
independent truth: glider-truth flies a log with a DVL's speed through water
(the true speed plus white noise), the speed is corrupted in known yos (scaled
by a factor, as gliderflight-adcp's yo 17 reads 0.65 of its neighbours), and
glider-diagnose's check must name exactly those yos. Printed: the hit rate by
corruption size and the false-exclusion rate of clean yos. Fresh seeds each
run (the run's seed is printed; --seed S replays it, --draw-seed D one log).

  tools/science/dvl_protocol/reference_check_truth.py --build build/release --logs 40 --jobs 2
"""
import argparse
import concurrent.futures
import json
import os
import random
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
# Corruption sizes (fraction of the speed, either way) and the bins they are reported in.
BINS = [(0.05, 0.10), (0.10, 0.15), (0.15, 0.20), (0.20, 0.30), (0.30, 0.45)]
# Hidden vertical effects drawn with the corruption (model-form error the check must survive).
EFFECTS = [None, "buoyancy_offset", "drag_change", "vertical_water_velocity", "hull_compressibility"]


def draw_effect(rng):
    e = rng.choice(EFFECTS)
    if e is None:
        return []
    value = {"buoyancy_offset": rng.choice([-1, 1]) * rng.uniform(0.010, 0.060),
             "drag_change": rng.uniform(1.08, 1.4),
             "vertical_water_velocity": rng.choice([-1, 1]) * rng.uniform(0.005, 0.02),
             "hull_compressibility": rng.uniform(0.5e-10, 3e-10)}[e]
    return ["--effect", f"{e}={value:.6g}"]


def one_log(build, draw_seed, workdir):
    rng = random.Random(draw_seed)
    truth_seed = rng.randrange(1, 2**31)
    yos = rng.randint(6, 10)
    noise = rng.uniform(0.005, 0.02)
    effect = draw_effect(rng)
    # 0, 1 or 2 corrupted yos (a third of the logs clean: the false-exclusion rate without any).
    corrupted = {}
    for y in rng.sample(range(yos), rng.choice([0, 1, 1, 2])):
        size = rng.uniform(BINS[0][0], BINS[-1][1])
        corrupted[y] = 1.0 + rng.choice([-1, 1]) * size
    csv = os.path.join(workdir, f"truth_{draw_seed}.csv")
    cmd = [os.path.join(build, "tools/science/truth/glider-truth"), "--seed", str(truth_seed), "--yos", str(yos),
           "--dvl-noise", f"{noise:.4f}", "--out", csv] + effect
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    lines = open(csv).read().splitlines(True)
    header = next(i for i, l in enumerate(lines) if not l.startswith("#"))
    names = lines[header].strip().split(",")
    yo_col, dvl_col = names.index("x_yo_count"), names.index("sci_speed_through_water")
    corrupted_means = {y: [] for y in corrupted}
    for i in range(header + 1, len(lines)):
        if lines[i].startswith("#"):
            continue
        f = lines[i].rstrip("\n").split(",")
        if f[dvl_col] == "" or f[yo_col] == "":
            continue
        y = int(float(f[yo_col]))
        if y in corrupted:
            f[dvl_col] = repr(float(f[dvl_col]) * corrupted[y])
            corrupted_means[y].append(float(f[dvl_col]))
            lines[i] = ",".join(f) + "\n"
    open(csv, "w").writelines(lines)
    run = subprocess.run([os.path.join(build, "tools/science/diagnose/glider-diagnose"), csv, "--vehicle",
                          os.path.join(ROOT, "boards/vehicles/slocum_shallow.toml"), "--plane", "vertical", "--json"],
                         capture_output=True, text=True)
    os.remove(csv)
    if run.returncode != 0:
        return {"draw_seed": draw_seed, "error": run.stderr.strip().splitlines()[-1:]}
    d = json.loads(run.stdout)
    by_yo = d["speed_through_water"]["by_yo"]
    # The diagnosis's yo k is the truth's x_yo_count k (a dive and the climb after it); checked here by the
    # corrupted yo's mean measured speed, which must be the corrupted one (the steady-glide subset of it).
    for y, values in corrupted_means.items():
        entry = next((b for b in by_yo if b["yo"] == y), None)
        if entry is None or not values or abs(entry["measured_mean_m_s"] / (sum(values) / len(values)) - 1) > 0.05:
            return {"draw_seed": draw_seed, "error": f"yo {y}: the diagnosis's yo numbering does not match"}
    flagged = {b["yo"] for b in by_yo if not b["reference_consistent"]}
    return {"draw_seed": draw_seed, "truth_seed": truth_seed, "yos": yos, "noise": noise, "effect": effect,
            "corrupted": corrupted, "flagged": sorted(flagged), "scored_yos": [b["yo"] for b in by_yo],
            "implied": {b["yo"]: b["implied_water_w_m_s"] for b in by_yo},
            "median": d["speed_through_water"]["implied_water_w_median_m_s"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=os.environ.get("GLIDER_BUILD_DIR", os.path.join(ROOT, "build/release")))
    ap.add_argument("--logs", type=int, default=40)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--seed", type=int, help="the run's seed (default: fresh)")
    ap.add_argument("--draw-seed", type=int, help="one log only, by its draw seed")
    ap.add_argument("--min-hit-above", type=float,
                    help="exit 1 unless every yo corrupted by more than this fraction is named")
    ap.add_argument("--max-false", type=int, help="exit 1 if more clean yos than this are excluded")
    args = ap.parse_args()
    seed = args.seed if args.seed is not None else random.SystemRandom().randrange(1, 2**31)
    run_rng = random.Random(seed)
    draws = [args.draw_seed] if args.draw_seed is not None else [run_rng.randrange(1, 2**62) for _ in range(args.logs)]
    if args.draw_seed is None:
        print(f"reference check on the truth: run seed {seed} ({args.logs} logs; replay: --seed {seed})")
    with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = list(pool.map(lambda s: one_log(args.build, s, work), draws))
    failed = [r for r in results if "error" in r]
    ok = [r for r in results if "error" not in r]
    hits = {b: [0, 0] for b in BINS}
    false_yos, clean_yos, misses, false_list = 0, 0, [], []
    for r in ok:
        for y in r["scored_yos"]:
            if y in r["corrupted"]:
                size = abs(r["corrupted"][y] - 1.0)
                b = next(b for b in BINS if b[0] <= size <= b[1])
                hits[b][1] += 1
                if y in r["flagged"]:
                    hits[b][0] += 1
                else:
                    misses.append((r["draw_seed"], y, r["corrupted"][y], r["implied"][y] - r["median"]))
            else:
                clean_yos += 1
                if y in r["flagged"]:
                    false_yos += 1
                    false_list.append((r["draw_seed"], y, r["implied"][y] - r["median"], r["effect"]))
    print(f"{len(ok)} logs diagnosed, {len(failed)} failed")
    print("| speed corruption | corrupted yos | named (hit) |\n|---|---|---|")
    for b in BINS:
        n, k = hits[b][1], hits[b][0]
        print(f"| {100 * b[0]:.0f}-{100 * b[1]:.0f} % | {n} | {k}/{n} ({100 * k / n:.0f} %) |" if n else
              f"| {100 * b[0]:.0f}-{100 * b[1]:.0f} % | 0 | - |")
    print(f"clean yos excluded (false exclusions): {false_yos}/{clean_yos}"
          f" ({100 * false_yos / max(1, clean_yos):.1f} %)")
    for s, y, f, dw in misses:
        print(f"  missed: --draw-seed {s} yo {y} factor {f:.3f} (implied w {1e3 * dw:+.1f} mm/s from the median)")
    for s, y, dw, e in false_list:
        print(f"  false: --draw-seed {s} yo {y} (implied w {1e3 * dw:+.1f} mm/s from the median) {' '.join(e)}")
    for r in failed:
        print(f"  failed: --draw-seed {r['draw_seed']}: {r['error']}")
    status = 0
    if args.min_hit_above is not None:
        bad = [m for m in misses if abs(m[2] - 1.0) > args.min_hit_above]
        if bad:
            print(f"FAIL: {len(bad)} yos corrupted by more than {100 * args.min_hit_above:.0f} % not named")
            status = 1
    if args.max_false is not None and false_yos > args.max_false:
        print(f"FAIL: {false_yos} clean yos excluded (at most {args.max_false})")
        status = 1
    if failed:
        status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
