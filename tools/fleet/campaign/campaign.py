# SPDX-License-Identifier: Apache-2.0
"""Campaigns: a card with parameters varied over many runs (docs/campaigns.md).
run: locally on all cores; shard: one chunk of runs (a Slurm array task);
status and report read whatever shards exist."""

import concurrent.futures
import hashlib
import math
import os
import shutil
import sys
import threading
import time

import cards
import report
import sampling
import shards
import sil_run
import slurm

RUNS_PER_SHARD = 50  # default chunk: a shard of the 30-day mission is ~20 min of one core


class CampaignError(Exception):
    """Bad input (a campaign file, a value, a results directory): exit 1."""


class CampaignUsageError(CampaignError):
    """Missing or conflicting arguments: exit 2 (README, exit codes)."""


def _flatten_vary(table, prefix=""):
    """[vary] names, quoted or nested; a table with distribution/grid/list/choice is a leaf."""
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict) and not {"distribution", "grid", "list", "choice"} & set(value):
            yield from _flatten_vary(value, name + ".")
        else:
            yield name, value


def load_campaign(path):
    doc = cards.read_toml(path)
    setup = cards.load_setup(doc, path, allowed_extra=("runs", "vary"))
    runs = doc.get("runs")
    if isinstance(runs, bool) or not isinstance(runs, int) or not runs >= 1:
        raise CampaignError(f"{path}: runs = {runs!r}: must be an integer >= 1")
    vary = dict(_flatten_vary(doc.get("vary", {})))
    if not vary:
        raise CampaignError(f"{path}: [vary] is empty: a campaign varies at least one parameter")
    try:
        for name, spec in vary.items():
            sampling.check_spec(name, spec)
    except sampling.SpecError as error:
        raise CampaignError(f"{path}: {error}") from error
    expect = doc.get("expect", {"result": "complete"})
    setup["expect"] = cards.parse_expectations(expect, path)
    with open(path, "rb") as f:
        digest = hashlib.sha256(f.read()).hexdigest()
    return {"name": setup["name"], "file": os.path.abspath(path), "sha256": digest, "setup": setup, "vary": vary,
            "runs": runs, "seed": setup["seed"]}


def new_manifest(path, shard_count, sil_binary):
    manifest = load_campaign(path)
    shard_count = shard_count or math.ceil(manifest["runs"] / RUNS_PER_SHARD)
    if not 1 <= shard_count <= manifest["runs"]:
        raise CampaignError(f"--shards {shard_count}: must be 1..{manifest['runs']} (the number of runs)")
    manifest["shards"] = shard_count
    manifest["sil"] = os.path.abspath(sil_binary) if os.path.sep in sil_binary else sil_binary
    return manifest


def run_one(manifest, run):
    """The deterministic record of run `run` and its wall time."""
    setup = manifest["setup"]
    seed = sampling.run_seed(manifest["seed"], run)
    params = dict(setup["set"])
    params.update(sampling.parameters(manifest["vary"], manifest["seed"], run))
    metrics, cost, error = sil_run.fly(manifest["sil"], setup, params, seed)
    rows = cards.check([tuple(e) for e in setup["expect"]], metrics, error)
    failed = [text for text, _, passed in rows if not passed]
    record = {"run": run, "seed": seed, "params": params, "metrics": metrics, "error": error,
              "passed": not failed, "failed": failed}
    return record, cost


def write_shard(directory, manifest, shard, started, results):
    payload = {"shard": shard, "campaign_sha256": manifest["sha256"], "host": os.uname().nodename,
               "started": started, "wall_s": time.time() - started, "records": [r for r, _ in results],
               "run_wall_s": [c["wall_s"] for _, c in results], "run_cpu_s": [c["cpu_s"] for _, c in results]}
    shards.write_shard(directory, shard, payload)
    return payload


def run_shards(directory, manifest, todo, jobs, on_run=None):
    """Flies the shards' runs on `jobs` workers, all in one queue; each shard
    is written as soon as its last run is done."""
    started = time.time()
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        queued = [(shard, [pool.submit(run_one, manifest, run) for run in range(*shards.shard_range(manifest, shard))])
                  for shard in todo]
        if on_run:
            for _, futures in queued:
                for future in futures:
                    future.add_done_callback(lambda _: on_run())
        return [write_shard(directory, manifest, shard, started, [f.result() for f in futures])
                for shard, futures in queued]


class Progress:
    """done/total, rate and ETA on stderr, at most every 2 s (and at the end)."""

    def __init__(self, total):
        self.total, self.done, self.start, self.last = total, 0, time.monotonic(), 0.0
        self.lock = threading.Lock()

    def tick(self):
        with self.lock:
            self.done += 1
            now = time.monotonic()
            if now - self.last < 2.0 and self.done < self.total:
                return
            self.last = now
            elapsed = now - self.start
            rate = self.done / elapsed if elapsed > 0 else 0.0
            eta = (self.total - self.done) / rate if rate > 0 else math.inf
            end = "\n" if self.done == self.total or not sys.stderr.isatty() else "\r"
            sys.stderr.write(f"campaign: {self.done}/{self.total} runs, {rate:.2f} runs/s, "
                             f"elapsed {elapsed:.0f} s, ETA {eta:.0f} s   {end}")
            sys.stderr.flush()


def default_out(manifest):
    return os.path.join(os.getcwd(), "build", "campaigns", manifest["name"])


def cmd_run(args):
    manifest = new_manifest(args.file, args.shards, args.sil)
    if args.first is not None:
        if not 1 <= args.first <= manifest["runs"]:
            raise CampaignError(f"--first {args.first}: must be 1..{manifest['runs']}")
        manifest["runs"] = args.first  # runs 0..N-1, each as in the full campaign
        manifest["shards"] = min(manifest["shards"], manifest["runs"])
    directory = args.out or default_out(manifest)
    directory, manifest = _prepare(directory, manifest)
    todo = shards.missing_shards(directory, manifest)
    total = sum(shards.shard_range(manifest, s)[1] - shards.shard_range(manifest, s)[0] for s in todo)
    print(f"campaign {manifest['name']}: {manifest['runs']} runs in {manifest['shards']} shards, "
          f"{len(todo)} to fly ({total} runs) on {args.jobs} cores -> {directory}", file=sys.stderr)
    progress = Progress(total)
    started = time.monotonic()
    run_shards(directory, manifest, todo, args.jobs, progress.tick)
    wall = time.monotonic() - started
    print(f"campaign: {total} runs in {wall:.1f} s wall on {args.jobs} cores", file=sys.stderr)
    return report.write_report(directory, manifest)


def _snapshot_inputs(directory, manifest):
    """Copies the vehicle, environment and TOML mission files into DIR/inputs
    and flies from the copies: editing a base file while a campaign runs (or
    between a shard and its resubmission) cannot change its runs. A Slocum
    .mi mission stays where it is (its .ma files are found next to it)."""
    inputs = os.path.join(directory, "inputs")
    os.makedirs(inputs, exist_ok=True)
    setup = manifest["setup"]
    for key in ("vehicle", "environment", "mission"):
        path = setup.get(key)
        if path is None or (key == "mission" and not path.endswith(".toml")):
            continue
        copy = os.path.join(inputs, f"{key}-{os.path.basename(path)}")
        shutil.copyfile(path, copy)
        setup[key] = copy


def _prepare(directory, manifest):
    """Creates the results directory (manifest and input copies), or checks
    it belongs to the same campaign; returns it and the manifest to fly."""
    directory = os.path.abspath(directory)
    if os.path.exists(os.path.join(directory, shards.MANIFEST)):
        old = shards.read_manifest(directory)
        keys = ("sha256", "runs", "shards", "seed")
        if any(old.get(k) != manifest.get(k) for k in keys):
            raise CampaignUsageError(f"{directory} holds results of another campaign or sharding "
                                     f"({', '.join(f'{k} {old.get(k)}' for k in keys)}): choose another --out")
        return directory, old
    os.makedirs(directory, exist_ok=True)
    _snapshot_inputs(directory, manifest)
    shards.write_manifest(directory, manifest)
    return directory, manifest


def cmd_shard(args):
    manifest = shards.read_manifest(args.dir)
    if not 0 <= args.shard < manifest["shards"]:
        raise CampaignError(f"--shard {args.shard}: must be 0..{manifest['shards'] - 1}")
    payload = run_shards(args.dir, manifest, [args.shard], max(1, args.jobs))[0]
    failed = sum(1 for r in payload["records"] if not r["passed"])
    print(f"shard {args.shard}: {len(payload['records'])} runs, {failed} failing, {payload['wall_s']:.1f} s")
    return 0


def cmd_status(args):
    manifest = shards.read_manifest(args.dir)
    done = shards.read_shards(args.dir, manifest)
    records = [r for payload in done.values() for r in payload["records"]]
    failed = sum(1 for r in records if not r["passed"])
    errors = sum(1 for r in records if r["error"])
    print(f"campaign {manifest['name']}: {len(done)}/{manifest['shards']} shards, "
          f"{len(records)}/{manifest['runs']} runs done, {failed} failing ({errors} could not fly)")
    missing = shards.missing_shards(args.dir, manifest)
    if missing:
        print(f"missing shards: {slurm.array_spec(missing)}")
    for line in slurm.job_states(args.dir):
        print(line)
    return 0


def cmd_report(args):
    manifest = shards.read_manifest(args.dir)
    return report.write_report(args.dir, manifest)


def cmd_submit(args):
    if args.resubmit:
        directory = os.path.abspath(args.file)
        manifest = shards.read_manifest(directory)
    else:
        manifest = new_manifest(args.file, args.shards, args.sil)
        directory, manifest = _prepare(args.out or default_out(manifest), manifest)
    return slurm.submit(directory, manifest, args)


def main(args):
    handlers = {"run": cmd_run, "shard": cmd_shard, "status": cmd_status, "report": cmd_report,
                "submit": cmd_submit}
    try:
        return handlers[args.command](args)
    except (FileNotFoundError, sampling.SpecError, slurm.SlurmError) as error:
        raise CampaignError(str(error)) from error
