# SPDX-License-Identifier: Apache-2.0
"""Fleet diagnosis: glider-diagnose over many flight logs, locally or as a
Slurm array (the campaigns' shards, atomic results and resubmission), and
one report that compares the vehicles and deployments: what the model gets
wrong in each log, the named cause, the fitted effects and the gain."""

import concurrent.futures
import hashlib
import json
import math
import os
import statistics
import subprocess
import sys
import time

import report
import shards
import slurm

LOGS_PER_SHARD = 8


class FleetError(Exception):
    """Bad input (a log, a value, a results directory): exit 1."""


class FleetUsageError(FleetError):
    """Missing or conflicting arguments: exit 2 (README, exit codes)."""


def log_metadata(path):
    """The '# key: value' header of a flight log (docs/flight-log.md)."""
    meta = {}
    with open(path, errors="replace") as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, sep, value = line[1:].partition(":")
            if sep:
                meta.setdefault(key.strip(), value.strip())
    return meta


def glider_name(meta):
    """The vehicle a log comes from: a real log's `glider`, a SIL log's vehicle."""
    if "glider" in meta:
        return meta["glider"].split()[0].rstrip(",")
    return meta.get("vehicle.name", "unknown")


def find_logs(arguments):
    logs = []
    for argument in arguments:
        if os.path.isdir(argument):
            for root, _, files in sorted(os.walk(argument)):
                logs += [os.path.join(root, f) for f in sorted(files) if f.endswith(".csv")]
        elif os.path.isfile(argument):
            logs.append(argument)
        else:
            raise FleetError(f"{argument}: no such log file or directory")
    if not logs:
        raise FleetError("no flight logs (*.csv) given or found")
    return [os.path.abspath(p) for p in logs]


def diagnose_one(manifest, log):
    meta = log_metadata(log)
    cmd = [manifest["diagnose"], log, "--json", "--model", manifest["model"]]
    if manifest.get("vehicle"):
        cmd += ["--default-vehicle", manifest["vehicle"]]
    start = time.monotonic()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=3600, check=False)
    except subprocess.TimeoutExpired:
        proc = None
    wall_s = time.monotonic() - start
    record = {"log": log, "glider": glider_name(meta), "deployment": os.path.splitext(os.path.basename(log))[0],
              "mission": meta.get("mission_file", meta.get("mission", "")), "error": ""}
    if proc is None or proc.returncode != 0:
        record["error"] = "timed out after 3600 s" if proc is None else diagnose_error(proc)
        return record, wall_s
    j = json.loads(proc.stdout)
    record.update({"model_vehicle": j["vehicle"], "samples": j["samples_used"], "cause": j["cause"],
                   "baseline_heldout_rms_m_s": j["baseline"]["heldout_rms_depth_rate_m_s"],
                   "extended_heldout_rms_m_s": j["extended"]["heldout_rms_depth_rate_m_s"], "gain": j["gain"],
                   "fitted": {f["effect"]: {"value": f["value"], "unit": f["unit"], "ci95": f.get("ci95")}
                              for f in j["findings"] if f.get("fitted")}})
    return record, wall_s


def diagnose_error(proc):
    """glider-diagnose's own message: with --json every program of the project
    (hal/core/cli) writes {"error": ..., "exit_code": N} on stdout; else its last
    stderr line (a usage error from the command line parser)."""
    try:
        message = json.loads(proc.stdout.strip().splitlines()[-1]).get("error")
        if message:
            return f"glider-diagnose: {message}"
    except (ValueError, IndexError, AttributeError):
        pass
    return (proc.stderr.strip().splitlines() or [f"exit status {proc.returncode}"])[-1]


def run_shard(directory, manifest, shard, jobs):
    first, end = shards.shard_range(manifest, shard)
    started = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda log: diagnose_one(manifest, log), manifest["logs"][first:end]))
    payload = {"shard": shard, "campaign_sha256": manifest["sha256"], "host": os.uname().nodename, "started": started,
               "wall_s": time.time() - started, "records": [r for r, _ in results],
               "run_wall_s": [w for _, w in results]}
    shards.write_shard(directory, shard, payload)
    return payload


def new_manifest(args):
    logs = find_logs(args.args)
    shard_count = args.shards or math.ceil(len(logs) / LOGS_PER_SHARD)
    if not 1 <= shard_count <= len(logs):
        raise FleetError(f"--shards {shard_count}: must be 1..{len(logs)} (the number of logs)")
    digest = hashlib.sha256("\n".join(logs).encode()).hexdigest()
    diagnose = os.path.abspath(args.diagnose) if os.path.sep in args.diagnose else args.diagnose
    return {"name": "fleet", "kind": "fleet", "logs": logs, "runs": len(logs), "shards": shard_count, "sha256": digest,
            "seed": 0, "model": args.model, "vehicle": os.path.abspath(args.vehicle) if args.vehicle else None,
            "diagnose": diagnose}


def _prepare(args):
    manifest = new_manifest(args)
    directory = os.path.abspath(args.out or os.path.join(os.getcwd(), "build", "fleet"))
    if os.path.exists(os.path.join(directory, shards.MANIFEST)):
        old = shards.read_manifest(directory)
        if old.get("sha256") != manifest["sha256"] or old.get("shards") != manifest["shards"]:
            raise FleetUsageError(f"{directory} holds another fleet diagnosis: choose another --out")
    else:
        shards.write_manifest(directory, manifest)
    return directory, manifest


def _gliders_table(records):
    by_glider = {}
    for r in records:
        by_glider.setdefault(r["glider"], []).append(r)
    lines = ["| glider | logs | causes named | held-out RMS, baseline -> extended (cm/s, median) | fitted effects (median) |",
             "|---|---|---|---|---|"]
    for glider, rs in sorted(by_glider.items()):
        ok = [r for r in rs if not r["error"]]
        causes = {}
        for r in ok:
            causes[r["cause"]] = causes.get(r["cause"], 0) + 1
        effects = {}
        for r in ok:
            for name, f in r["fitted"].items():
                effects.setdefault((name, f["unit"]), []).append(f["value"])
        rms = (f"{100 * statistics.median(r['baseline_heldout_rms_m_s'] for r in ok):.2f} -> "
               f"{100 * statistics.median(r['extended_heldout_rms_m_s'] for r in ok):.2f}") if ok else ""
        fitted = ", ".join(f"{n} {statistics.median(v):.4g} {u} ({len(v)})" for (n, u), v in sorted(effects.items()))
        lines.append(f"| {glider} | {len(rs)} ({len(rs) - len(ok)} failed) | "
                     f"{', '.join(f'{c} x{n}' for c, n in sorted(causes.items()))} | {rms} | {fitted} |")
    return lines


def write_report(directory, manifest):
    done, records, out = shards.merge(directory, manifest, "log")
    missing = slurm.array_spec(shards.missing_shards(directory, manifest))
    lines = [f"# Fleet diagnosis: {len(records)}/{manifest['runs']} logs ({manifest['model']} model)", ""]
    if missing:
        lines += [f"**Partial: shards {missing} missing.**", ""]
    lines += ["## By glider", ""] + _gliders_table(records) + ["", "## By deployment (log)", "",
              "| glider | deployment | samples | cause | held-out RMS baseline (cm/s) | extended (cm/s) | gain | fitted |",
              "|---|---|---|---|---|---|---|---|"]
    for r in records:
        if r["error"]:
            lines.append(f"| {r['glider']} | {r['deployment']} | | FAILED: {r['error']} | | | | |")
            continue
        fitted = ", ".join(f"{n} {f['value']:.4g} {f['unit']}" for n, f in sorted(r["fitted"].items()))
        lines.append(f"| {r['glider']} | {r['deployment']} | {r['samples']} | {r['cause']} | "
                     f"{100 * r['baseline_heldout_rms_m_s']:.2f} | {100 * r['extended_heldout_rms_m_s']:.2f} | "
                     f"{100 * r['gain']:.0f} % | {fitted} |")
    ok = [r for r in records if not r["error"]]
    if ok:
        with open(os.path.join(out, "rms.dat"), "w") as f:
            for i, r in enumerate(ok):
                f.write(f"{i} \"{r['deployment']}\" {100 * r['baseline_heldout_rms_m_s']!r} "
                        f"{100 * r['extended_heldout_rms_m_s']!r}\n")
        script = ("set title 'held-out depth-rate RMS per log: the nominal model and the diagnosed one'\n"
                  "set ylabel 'RMS (cm/s)'\nset style data histogram\nset style histogram clustered\n"
                  "set style fill solid 0.8\nset xtics rotate by -30\n"
                  "plot 'rms.dat' using 3:xtic(2) title 'nominal', '' using 4 title 'diagnosed'\n")
        if report._plot(out, "rms", script):
            lines += ["", "![held-out RMS per log](rms.png)"]
    walls = [w for p in done.values() for w in p["run_wall_s"]]
    if walls:
        lines += ["", f"{len(walls)} logs diagnosed in {sum(walls):.1f} s of wall time (max {max(walls):.1f} s a log)."]
    text = "\n".join(lines) + "\n"
    shards.write_atomically(os.path.join(out, "report.md"), text)
    print(text.split("![")[0].rstrip())
    print(f"\nreport: {os.path.join(out, 'report.md')}")
    return 0


def main(args):
    try:
        if args.action in ("run", "submit") and not args.resubmit:
            directory, manifest = _prepare(args)
        else:
            if len(args.args) != 1:
                raise FleetUsageError(f"fleet {args.action}: give the results directory")
            directory = os.path.abspath(args.args[0])
            manifest = shards.read_manifest(directory)
        if args.action == "run":
            for shard in shards.missing_shards(directory, manifest):
                print(f"fleet: shard {shard + 1}/{manifest['shards']}", file=sys.stderr)
                run_shard(directory, manifest, shard, max(1, args.jobs))
            return write_report(directory, manifest)
        if args.action == "shard":
            payload = run_shard(directory, manifest, args.shard, max(1, args.jobs))
            print(f"shard {args.shard}: {len(payload['records'])} logs, {payload['wall_s']:.1f} s")
            return 0
        if args.action == "submit":
            return slurm.submit(directory, manifest, args, ["fleet", "shard"])
        if args.action == "status":
            done = shards.read_shards(directory, manifest)
            print(f"fleet: {len(done)}/{manifest['shards']} shards, "
                  f"{sum(len(p['records']) for p in done.values())}/{manifest['runs']} logs diagnosed")
            missing = shards.missing_shards(directory, manifest)
            if missing:
                print(f"missing shards: {slurm.array_spec(missing)}")
            for line in slurm.job_states(directory):
                print(line)
            return 0
        return write_report(directory, manifest)
    except (FleetError, FileNotFoundError, slurm.SlurmError) as error:
        print(f"glider-campaign fleet: {error}", file=sys.stderr)
        return 2 if isinstance(error, FleetUsageError) else 1
