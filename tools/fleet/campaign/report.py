# SPDX-License-Identifier: Apache-2.0
"""The report a pilot reads, from whatever shards exist: completion,
abort causes with their run ids, time/energy/distance to complete, dead
reckoning error, waypoint arrival times, the failures ranked by the varied
parameter that best separates them from the passing runs; Markdown tables
and gnuplot PNG plots in DIR/report. report/results.jsonl is the merged
result, one line per run, identical wherever and however it was sharded."""

import math
import os
import shutil
import subprocess

import shards
import slurm

LISTED_RUN_IDS = 20


def percentile(values, q):
    """Nearest-rank percentile of a non-empty list."""
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, max(0, math.ceil(q / 100.0 * len(ordered)) - 1))]


def _stats_row(label, values, scale=1.0, digits=1):
    if not values:
        return f"| {label} | 0 | | | | |"
    v = [x * scale for x in values]
    f = f"{{:.{digits}f}}"
    return (f"| {label} | {len(v)} | {f.format(min(v))} | {f.format(percentile(v, 50))} | "
            f"{f.format(percentile(v, 90))} | {f.format(max(v))} |")


def _ids(runs):
    text = ", ".join(str(r) for r in runs[:LISTED_RUN_IDS])
    return text + (f", ... ({len(runs)} in all)" if len(runs) > LISTED_RUN_IDS else "")


def _entropy(failed, total):
    if total == 0 or failed in (0, total):
        return 0.0
    p = failed / total
    return -(p * math.log2(p) + (1 - p) * math.log2(1 - p))


def rank_parameters(records):
    """For each varied parameter, the one split (a threshold or one value)
    that best separates failing from passing runs, by information gain."""
    total, failed = len(records), sum(1 for r in records if not r["passed"])
    if total == 0 or failed == 0:
        return []
    base = _entropy(failed, total)
    ranking = []
    for name in sorted(records[0]["params"]):
        pairs = [(r["params"][name], not r["passed"]) for r in records]
        distinct = sorted({repr(v) for v, _ in pairs})
        numeric = all(isinstance(v, (int, float)) and not isinstance(v, bool) for v, _ in pairs)
        candidates = []
        if numeric and len(distinct) > 1:
            pairs.sort(key=lambda p: p[0])
            fails_below = 0
            for i in range(1, len(pairs)):
                fails_below += pairs[i - 1][1]
                if pairs[i][0] == pairs[i - 1][0]:
                    continue
                threshold = pairs[i - 1][0]
                below, above = (i, fails_below), (total - i, failed - fails_below)
                gain = base - (below[0] * _entropy(below[1], below[0]) + above[0] * _entropy(above[1], above[0])) / total
                worse = below if below[1] / below[0] >= above[1] / above[0] else above
                rule = f"{name} <= {threshold:.6g}" if worse is below else f"{name} > {threshold:.6g}"
                other = above if worse is below else below
                candidates.append((gain, rule, worse, other))
        elif len(distinct) > 1:
            for value in {repr(v): v for v, _ in pairs}.values():
                inside = [f for v, f in pairs if v == value]
                n_in, f_in = len(inside), sum(inside)
                outside = (total - n_in, failed - f_in)
                gain = base - (n_in * _entropy(f_in, n_in) + outside[0] * _entropy(outside[1], outside[0])) / total
                candidates.append((gain, f"{name} = {value}", (n_in, f_in), outside))
        if candidates:
            gain, rule, inside, outside = max(candidates, key=lambda c: c[0])
            ranking.append({"parameter": name, "rule": rule, "gain_bits": gain, "runs_in_rule": inside[0],
                            "failing_in_rule": inside[1], "runs_outside": outside[0], "failing_outside": outside[1],
                            "share_of_failures": inside[1] / failed})
    ranking.sort(key=lambda r: -r["gain_bits"])
    return ranking


def _rate(failing, runs):
    return f"{failing}/{runs} ({100.0 * failing / runs:.0f} %)" if runs else "0/0"


def _plot(directory, name, script):
    if not shutil.which("gnuplot"):
        return False
    with open(os.path.join(directory, f"{name}.gp"), "w") as f:
        f.write("set terminal pngcairo size 800,500 font 'DejaVu Sans,10'\n"
                f"set output '{name}.png'\nset termoption noenhanced\nset grid\n{script}")  # names keep their _
    proc = subprocess.run(["gnuplot", f"{name}.gp"], cwd=directory, capture_output=True, text=True, timeout=120,
                          check=False)
    return proc.returncode == 0


def _plots(out, records, ranking):
    """Mission time of every run against each varied numeric parameter
    (passing and failing runs apart), and the energy of the completed runs."""
    made = []
    numeric = [n for n in sorted(records[0]["params"]) if all(
        isinstance(r["params"][n], (int, float)) and not isinstance(r["params"][n], bool) for r in records)]
    order = [r["parameter"] for r in ranking if r["parameter"] in numeric]
    order += [n for n in numeric if n not in order]
    for name in order:
        safe = name.replace(".", "_")
        with open(os.path.join(out, f"vs_{safe}.dat"), "w") as f:
            for r in records:
                hours = r["metrics"].get("sim_time_s", float("nan")) / 3600.0
                f.write(f"{r['params'][name]!r} {hours!r} {0 if r['passed'] else 1} {r['run']}\n")
        script = (f"set title 'mission time against {name}'\nset xlabel '{name}'\nset ylabel 'simulated time (h)'\n"
                  f"plot 'vs_{safe}.dat' using 1:($3==0?$2:1/0) with points pt 7 ps 0.6 title 'pass', "
                  f"'' using 1:($3==1?$2:1/0) with points pt 2 ps 1.0 lc rgb 'red' title 'fail'\n")
        if _plot(out, f"vs_{safe}", script):
            made.append((f"vs_{safe}.png", f"mission time against {name} (red: failing runs)"))
    energy = [r["metrics"]["energy_kj"] for r in records if r["metrics"].get("result") == "complete"]
    if len(energy) > 1:
        with open(os.path.join(out, "energy.dat"), "w") as f:
            for i, e in enumerate(sorted(energy)):
                f.write(f"{e!r} {(i + 1) / len(energy)!r}\n")
        script = ("set title 'energy to complete (completed runs)'\nset xlabel 'energy (kJ)'\n"
                  "set ylabel 'fraction of runs'\nplot 'energy.dat' using 1:2 with steps notitle\n")
        if _plot(out, "energy", script):
            made.append(("energy.png", "energy to complete, cumulative over the completed runs"))
    return made


def _markdown(manifest, done_shards, records, ranking, plots, missing):
    runs_done = len(records)
    lines = [f"# Campaign {manifest['name']}", "",
             f"File `{manifest['file']}` (sha256 {manifest['sha256'][:12]}), seed {manifest['seed']}, "
             f"{manifest['runs']} runs in {manifest['shards']} shards.", ""]
    if missing:
        lines += [f"**Partial: {len(done_shards)}/{manifest['shards']} shards, {runs_done}/{manifest['runs']} runs; "
                  f"missing shards {missing}.**", ""]
    if not records:
        return lines + ["No results yet."]
    by_result = {}
    for r in records:
        by_result.setdefault(r["metrics"].get("result", "error"), []).append(r["run"])
    passed = sum(1 for r in records if r["passed"])
    lines += ["## Outcome", "", "| result | runs | share | run ids |", "|---|---|---|---|"]
    for result in ("complete", "aborted", "stopped", "error"):
        ids = by_result.get(result, [])
        if ids:
            lines.append(f"| {result} | {len(ids)} | {100.0 * len(ids) / runs_done:.1f} % | {_ids(ids)} |")
    lines += ["", f"Completion rate **{100.0 * len(by_result.get('complete', [])) / runs_done:.1f} %**; "
              f"{passed}/{runs_done} runs meet every expectation "
              f"({', '.join(e[0] for e in manifest['setup']['expect'])}).", ""]
    causes = {}
    for r in records:
        if r["metrics"].get("result") == "aborted":
            causes.setdefault(r["metrics"]["abort.cause"], []).append(r)
    if causes:
        lines += ["## Abort causes", "", "| cause | runs | abort time (h), median | run ids |", "|---|---|---|---|"]
        for cause, rs in sorted(causes.items(), key=lambda c: -len(c[1])):
            median = percentile([r["metrics"]["abort.time_s"] / 3600.0 for r in rs], 50)
            lines.append(f"| {cause} | {len(rs)} | {median:.2f} | {_ids([r['run'] for r in rs])} |")
        lines.append("")
    errors = [r for r in records if r["error"]]
    if errors:
        lines += ["## Runs that could not fly", ""]
        lines += [f"- run {r['run']}: {r['error']}" for r in errors[:LISTED_RUN_IDS]] + [""]
    complete = [r["metrics"] for r in records if r["metrics"].get("result") == "complete"]
    flown = [r["metrics"] for r in records if "sim_time_s" in r["metrics"]]
    lines += ["## Time, energy, distance and dead reckoning", "",
              "| quantity | runs | min | median | p90 | max |", "|---|---|---|---|---|---|",
              _stats_row("time to complete (h)", [m["sim_time_s"] for m in complete], 1 / 3600.0, 2),
              _stats_row("energy to complete (kJ)", [m["energy_kj"] for m in complete], 1.0, 0),
              _stats_row("charge to complete (Ah)", [m["charge_ah"] for m in complete], 1.0, 2),
              _stats_row("distance made good, start to end (km)", [m["distance_km"] for m in flown], 1.0, 2),
              _stats_row("DR error at surfacings (m/km travelled)",
                         [m["dr_error_m_per_km"] for m in flown if m.get("surfacings", 0) > 0], 1.0, 1),
              _stats_row("worst DR error at a surfacing (m)",
                         [m["dr_error_m"] for m in flown if m.get("surfacings", 0) > 0], 1.0, 1),
              _stats_row("yos", [m["yos"] for m in flown], 1.0, 0),
              _stats_row("max pitch error (deg)", [m["pitch_error_deg"] for m in flown], 1.0, 1), ""]
    waypoint_rows = []
    n = 1
    while True:
        times = [m[f"waypoint.{n}.reached_s"] for m in flown if f"waypoint.{n}.reached_s" in m]
        if not times:
            break
        waypoint_rows.append(_stats_row(f"waypoint {n} reached (h)", times, 1 / 3600.0, 2))
        n += 1
    if waypoint_rows:
        lines += ["## Waypoint arrival times (waypoints counted in order; runs = runs that got there)", "",
                  "| waypoint | runs | min | median | p90 | max |", "|---|---|---|---|---|---|", *waypoint_rows, ""]
    lines += ["## Varied parameters", "", "| parameter | min | median | max |", "|---|---|---|---|"]
    for name in sorted(records[0]["params"]):
        values = [r["params"][name] for r in records]
        if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values):
            lines.append(f"| {name} | {min(values):.6g} | {percentile(values, 50):.6g} | {max(values):.6g} |")
        else:
            lines.append(f"| {name} | {', '.join(sorted({str(v) for v in values}))} | | |")
    lines.append("")
    failing = [r for r in records if not r["passed"]]
    if failing:
        lines += ["## What the failing runs share", "",
                  "Each varied parameter's best single split of the runs (information gain in bits: how much "
                  "knowing the rule tells about pass/fail), best first.", "",
                  "| parameter | rule | failing inside the rule | failing outside | share of the failures | gain (bits) |",
                  "|---|---|---|---|---|---|"]
        for r in ranking:
            lines.append(f"| {r['parameter']} | `{r['rule']}` | {_rate(r['failing_in_rule'], r['runs_in_rule'])} | "
                         f"{_rate(r['failing_outside'], r['runs_outside'])} | {100.0 * r['share_of_failures']:.0f} % | "
                         f"{r['gain_bits']:.3f} |")
        lines += ["", "### Failing runs", "", "| run | failed expectations | parameters |", "|---|---|---|"]
        for r in failing[:50]:
            params = ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in r["params"].items())
            lines.append(f"| {r['run']} | {'; '.join(r['failed'])} | {params} |")
        if len(failing) > 50:
            lines.append(f"| ... | {len(failing) - 50} more in results.jsonl | |")
        lines.append("")
    walls = [w for payload in done_shards.values() for w in payload["run_wall_s"]]
    cpus = [c for payload in done_shards.values() for c in payload.get("run_cpu_s", [])]
    if walls:
        hosts = ", ".join(sorted({p["host"] for p in done_shards.values()}))
        lines += ["## Cost", "",
                  f"{len(walls)} runs: {sum(cpus):.1f} s of CPU (glider-sil's own user+system time: mean "
                  f"{sum(cpus) / max(1, len(cpus)):.3f} s, max {max(cpus, default=0.0):.3f} s a run), "
                  f"{sum(walls):.1f} s of run wall time (mean {sum(walls) / len(walls):.3f} s); shards on {hosts}.", ""]
    if plots:
        lines += ["## Plots", ""] + [f"![{caption}]({png})  \n{caption}" for png, caption in plots] + [""]
    return lines


def write_report(directory, manifest):
    done, records, out = shards.merge(directory, manifest, "run")
    ranking = rank_parameters(records)
    plots = _plots(out, records, ranking) if records else []
    missing = slurm.array_spec(shards.missing_shards(directory, manifest))
    text = "\n".join(_markdown(manifest, done, records, ranking, plots, missing)) + "\n"
    shards.write_atomically(os.path.join(out, "report.md"), text)
    # The terminal gets the report up to the plots.
    print(text.split("## Plots")[0].rstrip())
    print(f"\nreport: {os.path.join(out, 'report.md')}; merged results: {os.path.join(out, 'results.jsonl')}")
    return 0
