#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""sz -> the engine's receiver at 1 % byte corruption, over fresh seeds.

Each run of zmodem_lrzsz draws its corruption from a seed; the pty's splits
also vary, so a fixed seed is not a fixed run. This test takes fresh seeds
(from the clock, printed: `zmodem_lrzsz --direction from-sz --sizes
0,1,1024,4096 --corruption 0.01 --seed N` repeats one by hand) and runs them
one after another while its time budget lasts (at least MIN_SEEDS, at most
MAX_SEEDS; each run limited to LIMIT_S). Every run must deliver every file
byte-exact with sz exiting 0 (docs/comms.md, Zmodem, Limits: before the
receiver repeated its lost ZNAK/ZACK answers it stalled in 1 of 6 seeds).
Usage: check_lrzsz_corruption.py ZMODEM_LRZSZ. Exit 0 pass, 1 fail, 77 skipped."""
import os
import shutil
import subprocess
import sys
import tempfile
import time

tool = sys.argv[1]
MIN_SEEDS, MAX_SEEDS, BUDGET_S, LIMIT_S = 2, 6, 15.0, 20
if shutil.which("sz") is None:
    print("SKIPPED: lrzsz (sz) is not installed (Debian package lrzsz)")
    sys.exit(77)
first = int(time.time() * 1000) % 1000000
started = time.monotonic()
results = []
for k in range(MAX_SEEDS):
    if k >= MIN_SEEDS and time.monotonic() - started > BUDGET_S:
        break
    seed = first + k
    t0 = time.monotonic()
    trace = os.path.join(tempfile.gettempdir(), f"zmodem_trace_{os.getpid()}_{seed}.txt")
    run = subprocess.run([tool, "--direction", "from-sz", "--sizes", "0,1,1024,4096", "--corruption", "0.01",
                          "--seed", str(seed), "--limit-s", str(LIMIT_S)],
                         capture_output=True, text=True, timeout=LIMIT_S + 25, env={**os.environ, "ZMODEM_TRACE": trace})
    if run.returncode == 77:
        print(run.stdout)
        sys.exit(77)
    session = [line for line in run.stdout.splitlines() if line.startswith("session")]
    print(f"seed {seed}: {'PASS' if run.returncode == 0 else 'FAIL'} in {time.monotonic() - t0:.1f} s; "
          f"{session[0] if session else run.stdout[-500:]}")
    if run.returncode != 0:
        print(run.stdout[-2000:])
        # Each side's decoded headers with their times: where the run waited.
        print("trace tail (" + trace + "):\n" + "".join(open(trace).readlines()[-60:]) if os.path.exists(trace) else "")
    elif os.path.exists(trace):
        os.remove(trace)
    results.append(run.returncode == 0)
print(f"{sum(results)} of {len(results)} fresh seeds passed in {time.monotonic() - started:.1f} s")
sys.exit(0 if all(results) and len(results) >= MIN_SEEDS else 1)
