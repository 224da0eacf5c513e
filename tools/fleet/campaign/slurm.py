# SPDX-License-Identifier: Apache-2.0
"""Slurm: one `sbatch --array` job per submission, one array task per shard
(a chunk of runs), through Slurm's own commands (sbatch, squeue). The
results directory must be on a file system the nodes share; every task
writes its shard there atomically (shards.py)."""

import json
import os
import shlex
import shutil
import subprocess
import sys
import time

import shards

SUBMISSIONS = os.path.join("slurm", "submissions.json")
TOOL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "glider_campaign.py")


class SlurmError(Exception):
    pass


def array_spec(indices):
    """[0, 1, 2, 5, 7, 8] -> "0-2,5,7-8" (sbatch --array syntax)."""
    parts, indices = [], sorted(indices)
    i = 0
    while i < len(indices):
        j = i
        while j + 1 < len(indices) and indices[j + 1] == indices[j] + 1:
            j += 1
        parts.append(str(indices[i]) if i == j else f"{indices[i]}-{indices[j]}")
        i = j + 1
    return ",".join(parts)


def _submissions(directory):
    path = os.path.join(directory, SUBMISSIONS)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return json.load(f)


def active_tasks(directory):
    """{array index: state} of this directory's tasks Slurm still holds (pending, running, ...)."""
    jobs = {str(s["job"]) for s in _submissions(directory)}
    if not jobs or not shutil.which("squeue"):
        return {}
    proc = subprocess.run(["squeue", "-h", "-r", "-o", "%F %K %T"], capture_output=True, text=True, timeout=60,
                          check=False)
    if proc.returncode != 0:
        raise SlurmError(f"squeue failed: {proc.stderr.strip()}")
    states = {}
    for line in proc.stdout.splitlines():
        fields = line.split()
        if len(fields) == 3 and fields[0] in jobs and fields[1].isdigit():
            states[int(fields[1])] = fields[2]
    return states


def job_states(directory):
    try:
        states = active_tasks(directory)
    except (SlurmError, subprocess.TimeoutExpired) as error:
        return [f"slurm: {error}"]
    submissions = _submissions(directory)
    if not submissions:
        return []
    jobs = ", ".join(f"{s['job']} (shards {s['array']})" for s in submissions)
    lines = [f"slurm jobs: {jobs}"]
    by_state = {}
    for index, state in states.items():
        by_state.setdefault(state, []).append(index)
    for state, indices in sorted(by_state.items()):
        lines.append(f"  {state.lower()}: shards {array_spec(indices)}")
    if not states:
        lines.append("  no task queued or running")
    return lines


def write_script(directory, manifest, indices, args, number, command):
    name = f"glider-{manifest['name']}"[:64]
    lines = ["#!/bin/bash", f"# {manifest['name']}: shards {array_spec(indices)} of {manifest['shards']}",
             f"#SBATCH --job-name={name}", f"#SBATCH --array={array_spec(indices)}",
             f"#SBATCH --cpus-per-task={args.cpus_per_task}", f"#SBATCH --time={args.time}",
             f"#SBATCH --output={directory}/slurm/%A_%a.out"]
    if args.partition:
        lines.append(f"#SBATCH --partition={args.partition}")
    lines += ["set -euo pipefail",
              f"exec {shlex.quote(sys.executable)} {shlex.quote(TOOL)} {' '.join(command)} {shlex.quote(directory)} "
              '--shard "$SLURM_ARRAY_TASK_ID" --jobs "${SLURM_CPUS_PER_TASK:-1}"']
    path = os.path.join(directory, "slurm", f"job-{number}.sbatch")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def submit(directory, manifest, args, command=("shard",)):
    """Submits the shards not written yet and not queued or running; command: the tool's subcommand a task runs."""
    if not shutil.which("sbatch"):
        raise SlurmError("sbatch not found: Slurm's client commands (Debian: slurm-client) are needed")
    os.makedirs(os.path.join(directory, "slurm"), exist_ok=True)
    missing = shards.missing_shards(directory, manifest)
    active = active_tasks(directory)
    todo = [s for s in missing if s not in active]
    if not todo:
        print(f"nothing to submit: {len(missing)} shards missing, all of them queued or running "
              f"({array_spec(active) or 'none'})")
        return 0
    submissions = _submissions(directory)
    script = write_script(directory, manifest, todo, args, len(submissions), command)
    cmd = ["sbatch", "--parsable", *args.sbatch_arg, script]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120, check=False)
    if proc.returncode != 0:
        raise SlurmError(f"{' '.join(cmd)}: {proc.stderr.strip() or proc.returncode}")
    job = proc.stdout.strip().split(";")[0]
    submissions.append({"job": job, "array": array_spec(todo), "script": script, "submitted": time.time()})
    shards.write_atomically(os.path.join(directory, SUBMISSIONS), json.dumps(submissions, indent=1) + "\n")
    print(f"submitted job {job}: shards {array_spec(todo)} of {manifest['shards']} ({script})")
    print(f"  status: ./glider campaign status {directory}")
    return 0
