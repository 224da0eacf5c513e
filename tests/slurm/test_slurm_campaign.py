#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""A campaign on a real Slurm: a single-node cluster of its own
(single_node_cluster.py), `campaign submit` of box_small.toml in 3 shards,
one running array task killed (every run held at its start until then, so
the task cannot finish first), `status` on the partial results, `submit
--resubmit` of the missing shard, and the merged result compared byte for
byte with the same campaign run locally in a different number of shards.
Exit 77 (CTest: skipped) where a cluster cannot be started, with the reason.

Then fleet diagnosis of two real logs as a 2-task array, compared with the
same diagnosis run locally.

usage: test_slurm_campaign.py GLIDER_SIL GLIDER_DIAGNOSE"""

import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True
sys.path.insert(0, HERE)
import single_node_cluster  # noqa: E402

ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
TOOL = os.path.join(ROOT, "tools", "fleet", "campaign", "glider_campaign.py")
VEHICLE = os.path.join(ROOT, "boards", "vehicles", "slocum_we01.toml")
LOGS = [os.path.join(ROOT, "tests", "data", "real", f"comet-2019-222-02-{n}.csv") for n in (154, 156)]
CAMPAIGN = os.path.join(HERE, "box_small.toml")
SHARDS = 3


def tool(cluster, binaries, *args, timeout=600):
    proc = cluster.run(["/usr/bin/python3", TOOL, *binaries, *args], check=False, timeout=timeout)
    print(f"$ glider-campaign {' '.join(args)}\n{proc.stdout}{proc.stderr}", flush=True)
    if proc.returncode != 0:
        raise AssertionError(f"glider-campaign {args[0]} exited {proc.returncode}")
    return proc.stdout


def queue(cluster):
    """{array index: state} of every array task Slurm holds."""
    out = cluster.run(["squeue", "-h", "-r", "-o", "%K %T"]).stdout
    return {int(i): s for i, s in (line.split() for line in out.splitlines()) if i.isdigit()}


def wait_queue_empty(cluster, timeout_s):
    single_node_cluster.wait_for("the array tasks to finish", lambda: not queue(cluster), timeout_s,
                                 [cluster.path("slurmctld.log"), cluster.path("slurmd.log")])


def shard_file(directory, shard):
    return os.path.join(directory, "shards", f"shard-{shard:05d}.json")


def same_results(a_dir, b_dir, expected_lines):
    with open(os.path.join(a_dir, "report", "results.jsonl"), "rb") as f:
        a = f.read()
    with open(os.path.join(b_dir, "report", "results.jsonl"), "rb") as f:
        b = f.read()
    lines = a.count(b"\n")
    if lines != expected_lines or a != b:
        raise AssertionError(f"{a_dir} ({lines} lines, {expected_lines} expected) differs from {b_dir}")
    return len(a)


def fleet_on_slurm(cluster, diagnose):
    slurm_dir, local_dir = cluster.path("fleet-slurm"), cluster.path("fleet-local")
    tool(cluster, diagnose, "fleet", "submit", *LOGS, "--vehicle", VEHICLE, "--out", slurm_dir, "--shards", "2")
    wait_queue_empty(cluster, 300)
    if "2/2 shards" not in tool(cluster, diagnose, "fleet", "status", slurm_dir):
        raise AssertionError("fleet shards missing after the array job")
    tool(cluster, diagnose, "fleet", "report", slurm_dir)
    tool(cluster, diagnose, "fleet", "run", *LOGS, "--vehicle", VEHICLE, "--out", local_dir, "--shards", "1")
    with open(os.path.join(slurm_dir, "report", "results.jsonl")) as f:
        records = [json.loads(line) for line in f]
    if any(r["error"] or r["cause"] != "drag_change" for r in records):
        raise AssertionError("fleet: a log was not diagnosed (comet 2019: drag_change expected)")
    return same_results(slurm_dir, local_dir, 2)


def held_sil(cluster, sil_binary):
    """A glider-sil that waits at the start of every run while the file HOLD
    exists (300 s at most), then runs the real one with the same arguments.
    A task killed while HOLD exists has flown nothing and written no shard,
    however fast the machine: the kill cannot lose a race with the task."""
    hold = cluster.path("HOLD")
    wrapper = cluster.path("glider-sil-held")
    with open(wrapper, "w") as f:
        f.write(f"#!/bin/sh\ni=0\nwhile [ -e '{hold}' ] && [ $i -lt 3000 ]; do sleep 0.1; i=$((i + 1)); done\n"
                f"exec '{sil_binary}' \"$@\"\n")
    os.chmod(wrapper, 0o755)
    with open(hold, "w"):
        pass
    return wrapper, hold


def main(sil, diagnose):
    try:
        cluster = single_node_cluster.Cluster()
    except single_node_cluster.Unavailable as why:
        print(f"SKIPPED: no Slurm cluster can be started here: {why}")
        return 77
    try:
        cluster.start()
        print(f"cluster up in {cluster.dir}: node {cluster.host}, {cluster.cpus} CPUs", flush=True)
        slurm_dir = cluster.path("results-slurm")
        wrapper, hold = held_sil(cluster, sil[1])
        # Every task takes all CPUs: the shards run one after another, so the
        # first one can be seen running and killed while the others wait.
        out = tool(cluster, ["--sil", wrapper], "submit", CAMPAIGN, "--out", slurm_dir, "--shards", str(SHARDS),
                   "--cpus-per-task", str(cluster.cpus), "--time", "00:10:00")
        job = out.split()[2].rstrip(":")
        running = {}
        single_node_cluster.wait_for("an array task to run",
                                     lambda: running.update({k: v for k, v in queue(cluster).items()
                                                             if v == "RUNNING"}) or running, 60)
        victim = min(running)
        cluster.run(["scancel", f"{job}_{victim}"])
        print(f"killed array task {job}_{victim} while it ran (its run held at the start)", flush=True)
        single_node_cluster.wait_for(f"array task {victim} to leave the queue",
                                     lambda: victim not in queue(cluster), 120,
                                     [cluster.path("slurmctld.log"), cluster.path("slurmd.log")])
        os.remove(hold)  # the others fly now
        wait_queue_empty(cluster, 300)
        if os.path.exists(shard_file(slurm_dir, victim)):
            raise AssertionError(f"shard {victim} was written although its task was killed (finished first?)")
        others = [s for s in range(SHARDS) if s != victim]
        missing_others = [s for s in others if not os.path.exists(shard_file(slurm_dir, s))]
        if missing_others:
            raise AssertionError(f"shards {missing_others} missing although their tasks were not killed")
        status = tool(cluster, sil, "status", slurm_dir)
        if f"{SHARDS - 1}/{SHARDS} shards" not in status or f"missing shards: {victim}" not in status:
            raise AssertionError("status does not show the partial result and the killed shard")
        tool(cluster, sil, "report", slurm_dir)  # a report of the partial results
        out = tool(cluster, sil, "submit", "--resubmit", slurm_dir, "--cpus-per-task", str(cluster.cpus))
        if f"shards {victim} of {SHARDS}" not in out:
            raise AssertionError(f"--resubmit did not submit exactly shard {victim}")
        wait_queue_empty(cluster, 300)
        status = tool(cluster, sil, "status", slurm_dir)
        if f"{SHARDS}/{SHARDS} shards" not in status:
            raise AssertionError("shards still missing after the resubmission")
        tool(cluster, sil, "report", slurm_dir)
        local_dir = cluster.path("results-local")
        tool(cluster, sil, "run", CAMPAIGN, "--out", local_dir, "--shards", "2")
        size = same_results(slurm_dir, local_dir, 9)
        print(f"campaign: 9 runs, Slurm (3 shards, one killed and resubmitted) == local (2 shards), "
              f"{size} bytes identical", flush=True)
        size = fleet_on_slurm(cluster, diagnose)
        print(f"PASS: campaign as above; fleet diagnosis of 2 logs, Slurm (2 tasks) == local, {size} bytes identical")
        return 0
    finally:
        for name in ("glider-box_small", "glider-fleet"):
            subprocess.run(["scancel", "--name", name], env=cluster.env, capture_output=True, timeout=30, check=False)
        cluster.stop()


if __name__ == "__main__":
    sys.exit(main(["--sil", os.path.abspath(sys.argv[1])], ["--diagnose", os.path.abspath(sys.argv[2])]))
