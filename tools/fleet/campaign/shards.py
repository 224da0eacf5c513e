# SPDX-License-Identifier: Apache-2.0
"""A results directory shared by local runs, Slurm tasks, status and report:
manifest.json (everything a shard needs, so a task never rereads the
campaign file) and shards/shard-NNNNN.json, each written atomically (a
temporary file in the same directory, then rename) so a reader sees a
shard whole or not at all, even when its task is killed mid-write."""

import json
import os
import tempfile

MANIFEST = "manifest.json"


def write_atomically(path, text):
    directory = os.path.dirname(path) or "."
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", dir=directory)
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def shard_range(manifest, shard):
    """Runs [first, end) of a shard: contiguous chunks, sizes differ by at most one."""
    runs, shards = manifest["runs"], manifest["shards"]
    return shard * runs // shards, (shard + 1) * runs // shards


def shard_path(directory, shard):
    return os.path.join(directory, "shards", f"shard-{shard:05d}.json")


def write_manifest(directory, manifest):
    os.makedirs(os.path.join(directory, "shards"), exist_ok=True)
    write_atomically(os.path.join(directory, MANIFEST), json.dumps(manifest, indent=1, sort_keys=True) + "\n")


def read_manifest(directory):
    path = os.path.join(directory, MANIFEST)
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as error:
        raise FileNotFoundError(f"{path}: {error.strerror} (not a results directory?)") from error


def write_shard(directory, shard, payload):
    write_atomically(shard_path(directory, shard), json.dumps(payload, sort_keys=True) + "\n")


def read_shards(directory, manifest):
    """{shard: payload} of the shards written so far."""
    done = {}
    for shard in range(manifest["shards"]):
        path = shard_path(directory, shard)
        if os.path.exists(path):
            with open(path) as f:
                done[shard] = json.load(f)
    return done


def missing_shards(directory, manifest):
    return [s for s in range(manifest["shards"]) if not os.path.exists(shard_path(directory, s))]


def merge(directory, manifest, key):
    """The shards written so far, their records sorted by `key`, written to
    DIR/report/results.jsonl (one JSON line per record: the merged result,
    the same however the work was sharded); returns (shards, records, report dir)."""
    done = read_shards(directory, manifest)
    records = sorted((r for payload in done.values() for r in payload["records"]), key=lambda r: r[key])
    out = os.path.join(directory, "report")
    os.makedirs(out, exist_ok=True)
    write_atomically(os.path.join(out, "results.jsonl"), "".join(json.dumps(r, sort_keys=True) + "\n" for r in records))
    return done, records, out
