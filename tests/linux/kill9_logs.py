#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Logs that survive (issue 17 item 3, writer side): SIGKILL at random
moments of the target's flight-log writer (ring_log_writer, the real
RingBufferLog) and of glider-sil writing a long mission's log; after every
kill the file must hold the metadata, the header and whole rows (every line
ends with a newline and has the header's field count), except that a kill
during a write may leave the last line torn: Linux stops a write(2) to a file
at a page boundary when a fatal signal is pending, so no plain write is whole
against SIGKILL, and both writers here write fast (the SIL at 500,000x about
100 MB/s; the ring-log writer as fast as it can). The reader drops such a last
line and says so (tests/unit/test_flight_log_end.cpp, TruncatedAtEveryByte).
Never more than that last line.
Every kill comes after the file holds a whole row (the test waits for one,
then a seeded random time more), so each of the kills tests a log with rows
however loaded the machine is: no threshold on how many did.
Iterations and time are bounded; the random points are seeded and printed.

  kill9_logs.py RING_LOG_WRITER GLIDER_SIL SOURCE_DIR OUT_DIR
"""
import os
import random
import signal
import subprocess
import sys
import time

ITERATIONS = 25  # per writer
FIRST_ROW_TIMEOUT_S = 30  # a writer that has written no whole row by then is broken, not slow


def fail(message):
    print("FAIL kill9_logs: " + message)
    sys.exit(1)


def check_whole_rows(path, name, iteration, torn_tail_allowed):
    with open(path, "rb") as f:
        data = f.read()
    if not data:
        return 0, False  # killed before the file had its header: nothing torn
    torn = not data.endswith(b"\n")
    if torn and not torn_tail_allowed:
        fail("%s iteration %d: the file ends inside a row (%r)" % (name, iteration, data[-60:]))
    if torn:
        data = data[:data.rfind(b"\n") + 1]  # what the reader keeps
    lines = data.decode().split("\n")[:-1]
    header = None
    rows = 0
    for number, line in enumerate(lines, 1):
        if line.startswith("#"):
            if header is not None and not line.startswith("# end: "):
                fail("%s iteration %d: line %d: comment after the header" % (name, iteration, number))
            continue
        if header is None:
            header = line.count(",")
            continue
        if line.count(",") != header:
            fail("%s iteration %d: line %d has %d fields, the header %d"
                 % (name, iteration, number, line.count(",") + 1, header + 1))
        rows += 1
    return rows, torn


def has_a_whole_row(path):
    """The file's start holds the header line and one whole row after it."""
    try:
        with open(path, "rb") as f:
            start = f.read(65536)
    except FileNotFoundError:
        return False
    lines = [line for line in start.split(b"\n")[:-1] if not line.startswith(b"#")]
    return len(lines) >= 2


def wait_for_first_row(proc, path, name, iteration):
    deadline = time.monotonic() + FIRST_ROW_TIMEOUT_S
    while not has_a_whole_row(path):
        if proc.poll() is not None:
            fail("%s iteration %d: the writer exited (status %s) before writing a row" % (name, iteration, proc.returncode))
        if time.monotonic() > deadline:
            proc.kill()
            proc.wait(timeout=10)
            fail("%s iteration %d: no whole row in %s after %d s" % (name, iteration, path, FIRST_ROW_TIMEOUT_S))
        time.sleep(0.005)


def kill_runs(name, command, path, rng, max_delay_s, torn_tail_allowed=False):
    """Kills come at a random moment in [0, max_delay_s] s after the first whole row is in the file."""
    total_rows = 0
    with_rows = 0
    torn_tails = 0
    for iteration in range(ITERATIONS):
        if os.path.exists(path):
            os.remove(path)
        proc = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        wait_for_first_row(proc, path, name, iteration)
        time.sleep(rng.uniform(0.0, max_delay_s))
        proc.send_signal(signal.SIGKILL)
        proc.wait(timeout=10)
        rows, torn = check_whole_rows(path, name, iteration, torn_tail_allowed)
        torn_tails += torn
        total_rows += rows
        with_rows += rows > 0
    if with_rows != ITERATIONS:  # every kill came after a whole row was in the file
        fail("%s: only %d of %d killed logs hold a whole row" % (name, with_rows, ITERATIONS))
    print("%s: %d kills, %d with rows, %d whole rows in all, %d torn last lines (write cut by the kill), no other torn row"
          % (name, ITERATIONS, with_rows, total_rows, torn_tails))


def main():
    writer, sil, source, out_dir = sys.argv[1:5]
    os.makedirs(out_dir, exist_ok=True)
    seed = int(os.environ.get("GLIDER_KILL9_SEED", "12"))
    rng = random.Random(seed)
    print("seed %d" % seed)
    target_log = os.path.join(out_dir, "target.csv")
    # The target's writer thread drains the ring every 0.5 s: kills span the next two drains.
    kill_runs("target ring log", [writer, target_log], target_log, rng, 1.0, torn_tail_allowed=True)
    sil_log = os.path.join(out_dir, "sil.csv")
    kill_runs("glider-sil", [sil, "--quiet", "--vehicle", os.path.join(source, "boards/vehicles/slocum_we01.toml"),
                             "--mission", os.path.join(source, "boards/missions/month_200m.toml"), "--out", sil_log],
              sil_log, rng, 0.3, torn_tail_allowed=True)
    print("PASS kill9_logs")


if __name__ == "__main__":
    main()
