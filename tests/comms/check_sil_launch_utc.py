#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil names its Slocum segments from the mission's simulated UTC
start, as a glider does from its clock (docs/comms.md, End to end):
--launch-utc 2026-07-02T11:27:05Z gives `slocum_we01-2026-182-00-000.sbd`
(day of the year counted from 0: 2 July = 182) and that fileopen_time; the
default is the time of the run (never 1970); a bad value is refused (exit 2,
naming the option, the value and what is allowed).
Usage: check_sil_launch_utc.py GLIDER_SIL SOURCE_DIR. Exit 0 = pass."""
import datetime
import os
import shutil
import subprocess
import sys
import tempfile

glider_sil, source = sys.argv[1], sys.argv[2]
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def fly(folder, *extra):
    return subprocess.run([glider_sil, "--mission", f"{source}/boards/missions/box_current/missions/box.mi",
                           "--vehicle", f"{source}/boards/vehicles/slocum_we01.toml", "--max-sim-time-s", "600",
                           "--slocum-dir", folder, "--quiet", *extra], capture_output=True, text=True, timeout=50)


work = tempfile.mkdtemp(prefix="sil_launch_utc_")
try:
    given = os.path.join(work, "given")
    run = fly(given, "--launch-utc", "2026-07-02T11:27:05Z")
    check(run.returncode in (0, 3), f"glider-sil flew (exit {run.returncode}) {run.stderr.strip()}")
    names = sorted(os.listdir(given)) if os.path.isdir(given) else []
    check("slocum_we01-2026-182-00-000.sbd" in names and "slocum_we01-2026-182-00-000.dbd" in names,
          f"names from the launch UTC: {[n for n in names if n.endswith('bd')]}")
    header = open(os.path.join(given, "slocum_we01-2026-182-00-000.sbd"), "rb").read(1024).decode("latin-1") \
        if "slocum_we01-2026-182-00-000.sbd" in names else ""
    check("fileopen_time:    Thu_Jul__2_11:27:05_2026" in header, "fileopen_time: the launch UTC")
    check("full_filename:    slocum_we01-2026-182-0-0" in header, "full_filename: the launch UTC's day")

    default = os.path.join(work, "default")
    before = datetime.datetime.now(datetime.timezone.utc)
    run = fly(default)
    after = datetime.datetime.now(datetime.timezone.utc)
    names = sorted(n for n in os.listdir(default) if n.endswith(".sbd")) if os.path.isdir(default) else []
    days = {f"slocum_we01-{d.year:04d}-{d.timetuple().tm_yday - 1:03d}-00-000.sbd" for d in (before, after)}
    check(bool(names) and names[0] in days, f"default: the run's own UTC day ({names[:1]}, expected one of {days})")

    for bad in ("2026-02-30T00:00:00Z", "2026-07-02 11:27:05", "1999-12-31T23:59:59Z", "nan", "2026-07-02T24:00:00Z"):
        run = fly(os.path.join(work, "bad"), "--launch-utc", bad)
        check(run.returncode == 2 and "--launch-utc" in run.stderr and bad in run.stderr and "2099" in run.stderr,
              f"--launch-utc {bad!r} refused (exit {run.returncode}): {run.stderr.strip()}")
    check(not os.path.exists(os.path.join(work, "bad")), "nothing written for a refused launch time")
finally:
    shutil.rmtree(work, ignore_errors=True)
print("PASS" if not failures else f"FAILED: {len(failures)}")
sys.exit(0 if not failures else 1)
