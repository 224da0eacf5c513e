#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""glider-campaign: flight test cards (regress), Monte-Carlo campaigns run
locally or on Slurm (run, submit, status, report), and fleet diagnosis.
./glider calls it with the built binaries; docs/campaigns.md is the manual."""

import argparse
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree (it may be read-only, or shared by Slurm nodes)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import campaign  # noqa: E402
import cards  # noqa: E402
import regress  # noqa: E402


def main(argv):
    parser = argparse.ArgumentParser(prog="glider-campaign", description=__doc__)
    parser.add_argument("--sil", default=os.environ.get("GLIDER_SIL", "glider-sil"), help="the glider-sil binary")
    parser.add_argument("--diagnose", default=os.environ.get("GLIDER_DIAGNOSE", "glider-diagnose"),
                        help="the glider-diagnose binary")
    sub = parser.add_subparsers(dest="command", required=True)

    p = sub.add_parser("regress", help="fly flight test cards, table + JUnit XML, exit 1 on a failure")
    p.add_argument("cards", nargs="+", help="card files or directories of them")
    p.add_argument("--junit", help="write JUnit XML here")
    p.add_argument("--jobs", type=int, default=os.cpu_count())

    p = sub.add_parser("run", help="run a campaign locally on all cores")
    p.add_argument("file")
    p.add_argument("--out", help="results directory (default: build/campaigns/NAME)")
    p.add_argument("--jobs", type=int, default=os.cpu_count())
    p.add_argument("--shards", type=int, help="result files to write (default: one per 50 runs)")
    p.add_argument("--first", type=int, help="fly only runs 0..N-1 (a sample: run i is the same as in the full campaign)")

    p = sub.add_parser("submit", help="write and submit an sbatch --array job; --resubmit: the missing shards")
    p.add_argument("file", help="campaign file, or with --resubmit its results directory")
    p.add_argument("--out", help="results directory on a file system the nodes share")
    p.add_argument("--partition")
    p.add_argument("--shards", type=int)
    p.add_argument("--cpus-per-task", type=int, default=1)
    p.add_argument("--time", default="04:00:00", help="sbatch --time of one shard")
    p.add_argument("--resubmit", action="store_true")
    p.add_argument("--sbatch-arg", action="append", default=[], help="extra sbatch argument (repeatable)")

    p = sub.add_parser("shard", help="run one shard (what a Slurm array task runs)")
    p.add_argument("dir")
    p.add_argument("--shard", type=int, default=int(os.environ.get("SLURM_ARRAY_TASK_ID", "-1")))
    p.add_argument("--jobs", type=int, default=int(os.environ.get("SLURM_CPUS_PER_TASK", os.cpu_count())))

    p = sub.add_parser("status", help="shards done, runs done and failing, Slurm job states")
    p.add_argument("dir")

    p = sub.add_parser("report", help="merge the shards there are and write the report")
    p.add_argument("dir")

    p = sub.add_parser("fleet", help="diagnose many flight logs (locally or as a Slurm array), one report")
    p.add_argument("action", choices=["run", "submit", "shard", "report", "status"])
    p.add_argument("args", nargs="*", help="run/submit: LOG files or directories; else the results dir")
    p.add_argument("--out")
    p.add_argument("--vehicle", help="vehicle file for logs without one")
    p.add_argument("--shards", type=int)
    p.add_argument("--shard", type=int, default=int(os.environ.get("SLURM_ARRAY_TASK_ID", "-1")))
    p.add_argument("--model", choices=["steady", "dynamic"], default="steady",
                   help="glider-diagnose --model (steady: ~3 s a log, dynamic: ~20 s)")
    p.add_argument("--partition")
    p.add_argument("--jobs", type=int, default=int(os.environ.get("SLURM_CPUS_PER_TASK", os.cpu_count())))
    p.add_argument("--cpus-per-task", type=int, default=1)
    p.add_argument("--time", default="04:00:00", help="sbatch --time of one shard")
    p.add_argument("--resubmit", action="store_true")
    p.add_argument("--sbatch-arg", action="append", default=[])

    args = parser.parse_args(argv)
    try:
        if args.command == "regress":
            return regress.run(args.cards, args.sil, args.junit, max(1, args.jobs))
        if args.command == "fleet":
            import fleet  # noqa: E402  (its own module: diagnosis, not flights)
            return fleet.main(args)
        return campaign.main(args)
    except (cards.CardError, campaign.CampaignError) as error:
        print(f"glider-campaign: {error}", file=sys.stderr)
        # README's exit codes: a bad file or value is 1, missing or conflicting arguments 2.
        return 2 if isinstance(error, campaign.CampaignUsageError) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
