#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil's Slocum files end to end (docs/slocum-binary.md, "Writing").

1. A refused sbdlist.dat: exit 1, the message names file:line and the sensor.
2. The box mission with --out, --slocum-dir and --launch-utc: glider-convert
   reads the .dbd folder back with one row per CSV row; its m_present_time is
   the CSV's time (seconds since launch) plus the launch UTC (Unix seconds, as
   a Slocum's clock).
3. kill -9 of glider-sil mid-flight (a power cut): every segment closed before
   it ends with the end marker and converts; nothing else is needed to read them.

usage: check_sil_slocum.py GLIDER_SIL GLIDER_CONVERT SOURCE_DIR WORK_DIR
"""
import csv
import os
import shutil
import signal
import subprocess
import sys
import time


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def csv_rows(path):
    with open(path, newline="") as f:
        lines = [line for line in f if not line.startswith("#")]
    reader = csv.reader(lines)
    header = next(reader)
    return header, list(reader)


def main():
    sil, convert, source, work = sys.argv[1:5]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    vehicle = os.path.join(source, "boards/vehicles/slocum_comet.toml")

    # 1. A bad sbdlist.dat.
    bad = os.path.join(work, "sbdlist.dat")
    with open(bad, "w") as f:
        f.write("m_present_time\nm_depth nan\n")
    run = subprocess.run([sil, "--vehicle", vehicle, "--mission", os.path.join(source, "boards/missions/box_current/missions/box.mi"),
                          "--slocum-dir", os.path.join(work, "bad"), "--sbdlist", bad, "--quiet"],
                         capture_output=True, text=True, timeout=30)
    if run.returncode != 1 or bad + ":2: sensor m_depth: decimation 'nan'" not in run.stderr:
        fail("bad sbdlist.dat: exit %d, stderr %r" % (run.returncode, run.stderr))
    if os.path.exists(os.path.join(work, "bad")):
        fail("a refused sbdlist.dat still made the Slocum directory")
    print("refused: " + run.stderr.strip().splitlines()[-1])

    # 2. A flight, its CSV and its .dbd read back by glider-convert.
    slocum = os.path.join(work, "box")
    flight_csv = os.path.join(work, "box.csv")
    run = subprocess.run([sil, "--vehicle", vehicle, "--mission", os.path.join(source, "boards/missions/box_current/missions/box.mi"),
                          "--out", flight_csv, "--slocum-dir", slocum, "--launch-utc", "2026-07-02T11:27:05Z"],
                         capture_output=True, text=True, timeout=30)
    if run.returncode != 0:
        fail("glider-sil: exit %d: %s" % (run.returncode, run.stderr))
    summary = [line for line in run.stdout.splitlines() if "slocum files" in line]
    print(summary[0].strip() if summary else "no slocum line in the summary")
    dbd = sorted(n for n in os.listdir(slocum) if n.endswith(".dbd"))
    sbd = sorted(n for n in os.listdir(slocum) if n.endswith(".sbd"))
    if len(dbd) < 10 or len(sbd) != len(dbd) or not os.listdir(os.path.join(slocum, "cac")):
        fail("expected a .dbd and an .sbd per segment and the caches: %s" % sorted(os.listdir(slocum)))
    converted = os.path.join(work, "box-dbd.csv")
    run = subprocess.run([convert] + [os.path.join(slocum, n) for n in dbd] + ["--out", converted],
                         capture_output=True, text=True, timeout=30)
    if run.returncode != 0:
        fail("glider-convert: exit %d: %s" % (run.returncode, run.stderr))
    header, rows = csv_rows(flight_csv)
    dbd_header, dbd_rows = csv_rows(converted)
    if len(rows) != len(dbd_rows):
        fail("%d CSV rows, %d converted .dbd rows" % (len(rows), len(dbd_rows)))
    launch = 1782991625.0  # 2026-07-02T11:27:05Z
    for a, b in zip(rows, dbd_rows):
        if abs(float(a[0]) + launch - float(b[0])) > 1e-5:
            fail("times differ: CSV %s + launch %.0f vs .dbd %s" % (a[0], launch, b[0]))
    missing = [n for n in header if not n.startswith(("sim_", "sci_")) and n not in dbd_header]
    print("glider-convert: %d rows, %d columns; firmware columns never set (not in the .dbd read): %s"
          % (len(dbd_rows), len(dbd_header), missing))

    # 3. kill -9 mid-flight.
    killed = os.path.join(work, "killed")
    month = os.path.join(source, "boards/missions/month_waypoints/missions/month.mi")
    process = subprocess.Popen([sil, "--vehicle", vehicle, "--mission", month, "--max-working-depth-m", "200",
                                "--slocum-dir", killed, "--quiet"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    third = None
    deadline = time.monotonic() + 40
    while time.monotonic() < deadline and process.poll() is None:
        names = sorted(n for n in os.listdir(killed) if n.endswith(".dbd")) if os.path.isdir(killed) else []
        if len(names) >= 4:
            third = names
            break
        time.sleep(0.01)
    if third is None:
        process.kill()
        fail("glider-sil ended (or was too slow) before its fourth segment: nothing to cut")
    process.send_signal(signal.SIGKILL)
    process.wait()
    names = sorted(n for n in os.listdir(killed) if n.endswith(".dbd"))
    closed = names[:-1]  # the last one may be open at the kill
    for name in closed:
        with open(os.path.join(killed, name), "rb") as f:
            if not f.read().endswith(b"X"):
                fail(name + " was closed before the kill but does not end with its end marker")
    run = subprocess.run([convert] + [os.path.join(killed, n) for n in closed] + ["--out", os.path.join(work, "killed.csv")],
                         capture_output=True, text=True, timeout=30)
    if run.returncode != 0 or "warning" in run.stderr.lower():
        fail("the closed segments after kill -9 do not convert cleanly: %s" % run.stderr)
    _, killed_rows = csv_rows(os.path.join(work, "killed.csv"))
    print("kill -9 after %d segments: %d closed segments read whole (%d rows)" % (len(names), len(closed), len(killed_rows)))


if __name__ == "__main__":
    main()
