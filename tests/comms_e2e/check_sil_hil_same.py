#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The same mission in SIL gives the same surfacings and files as in HIL
(issue 23). The HIL goto case of check_hil_e2e.py (glider-firmware against
glider-plant at time scale 100 and a real glider-shore; it checks itself and
keeps its folders), then the same mission, vehicle, seed, launch point and
heading in glider-sil against a real glider-shore with the same options, the
pilot's goto and truncated copy queued at the same points (after the first
event; after the goto went out and its call's event is written). What the two
shores received is compared:
- the number of calls (surfacing events) and of accepted/refused uploads, and
  in which call each happened;
- the .sbd files fetched: the same mission and segment numbers (the
  `-MM-SSS` of `<name>-<yyyy>-<ddd>-<mission>-<segment>`) in the same calls,
  the same sensor list (sensor_list_crc, sensors_per_cycle). The names' other
  parts differ by design: the glider's name (the board's in HIL, the vehicle
  file's in SIL) and the date (HIL: the wall clock; SIL: its --launch-utc, by
  default the time of the run: the same day unless a run crosses midnight).
  The bytes differ too: the rows hold times and the sensors' noise drawn at
  other instants (below);
- each surfacing's fix, within the tolerance stated at GPS_TOL_M and PER_DIVE_TOL_M; the
  times are printed only (why: at the tolerances).
Usage: check_sil_hil_same.py BUILD_DIR SOURCE_DIR. Exit 0 pass, 1 fail, 77 skip."""
import glob
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

import hil_goto_mission

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../comms"))
import shore_run  # noqa: E402

build, source = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
here = os.path.dirname(os.path.abspath(__file__))
NAME = "unit_345"
# Why SIL and HIL differ at all: SIL steps the plant and the firmware in
# lockstep, the firmware's 1 s cycle on exact simulated instants; in HIL the
# firmware wakes on the wall clock (time scale 100: a 10 ms cycle, woken late
# by up to a few ms on this machine, i.e. under one simulated cycle), the
# plant integrates on its own steps and serves the sensors as sampled at the
# instant they are read. So every decision the firmware takes on a threshold
# or a timer (dive, each inflection, the surfacing request) can fall one
# cycle earlier or later than in SIL, and the noise streams (same seed) are
# drawn at other instants: the two runs' GPS errors are independent draws.
# The tolerance on each fix, from those causes (not from a run):
# - GPS: 3 m 1-sigma per axis (SimGps noise_m, the plant's the same), so the
#   difference of two fixes is 3*sqrt(2) m per axis, and their distance
#   (Rayleigh) exceeds 3*sqrt(2)*sqrt(-2 ln 0.001) = 15.8 m once in 1000;
# - decisions: at most one 1 s cycle each, at most 0.5 m/s horizontal speed
#   (the WE01 flies 0.3-0.4 m/s), at most 12 decisions a dive (the dive, the
#   yo's inflections: 5-20 m half cycles of >= 75 s in a dive of <= 800 s,
#   and the surfacing), so 6 m more per dive since the launch call, added up
#   (the goto steers both runs to the same waypoint, so the sum is a bound).
GPS_TOL_M = 3.0 * math.sqrt(2.0) * math.sqrt(-2.0 * math.log(0.001))
PER_DIVE_TOL_M = 12 * 1.0 * 0.5
# The times are printed, not compared: a surfacing's mission time counts the
# earlier calls, held at the surface while the shore works. In HIL a call's
# simulated length is its wall length times 100; in SIL the lockstep run waits
# for the shore (up to 20 ms a cycle while connected, docs/comms.md), so the
# same call lasts other simulated seconds (in still water the vehicle does not
# move at the surface: the fixes are unaffected).
# SIL calls the shore in lockstep with its answers (TcpShore waits for the
# shore between cycles, however loaded the machine); between calls it runs at
# this time scale so that the pilot's queue (this script, reacting to an
# event) lands before the next call as in HIL: 500-700 s between surfacings
# = 2-2.8 s of wall time.
SIL_TIME_SCALE = 250
check = shore_run.Checks()
failures = check.failures
procs = []


def header_of(path):
    head = {}
    for line in open(path, "rb").read(4096).split(b"\n"):
        m = re.match(rb"^(\w+):\s*(.*)$", line)
        if not m:
            break
        head[m.group(1).decode()] = m.group(2).decode().strip()
    return head


def distance_m(a, b):
    k = math.pi / 180.0
    x = (b[1] - a[1]) * k * math.cos(0.5 * (a[0] + b[0]) * k)
    return 6371000.0 * math.hypot(x, (b[0] - a[0]) * k)


def summary(events, journals):
    """Per call: mission time since the launch call, fix, .sbd segments received, upload outcome."""
    mt0 = events[0]["glider_time"]["mission_time_s"]
    calls = []
    for e, j in zip(events, journals):
        calls.append({
            "t": e["glider_time"]["mission_time_s"] - mt0,
            "fix": (e["gps"]["lat_deg"], e["gps"]["lon_deg"]),
            "sbd": sorted(shore_run.segment_of(f["name"]) for f in e["files_received"] if f["name"].endswith(".sbd")),
            "accepted": "goto_l10.ma accepted" in j,
            "refused": "goto_l10.ma refused (the old plan is flown)" in j,
        })
    return calls


glider_sil = os.path.join(build, "sil/glider-sil")
shore_bin = os.path.join(build, "tools/shore/station/glider-shore")
work = tempfile.mkdtemp(prefix="sil_hil_same_")
try:
    hil_keep = os.path.join(work, "hil")
    started = time.monotonic()
    hil = subprocess.run([sys.executable, os.path.join(here, "check_hil_e2e.py"), build, source, "goto", "--keep",
                          hil_keep], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=55)
    print("HIL goto run (check_hil_e2e.py goto): exit %d, %.1f s wall" % (hil.returncode, time.monotonic() - started))
    if hil.returncode == 77 or not os.path.exists(glider_sil):
        print(hil.stdout[-500:])
        print("SKIP: the HIL run or glider-sil is not available")
        sys.exit(77)
    check(hil.returncode == 0, "the HIL run passed its own checks")
    if hil.returncode != 0:
        print(hil.stdout[-3000:])

    sil_work = os.path.join(work, "sil")
    os.makedirs(sil_work)
    mission, mi, goto, broken = hil_goto_mission.prepare(source, sil_work, "goto")
    root = os.path.join(sil_work, "shore")
    slocum = os.path.join(sil_work, "slocum")
    # The HIL shore's options (check_hil_e2e.py, goto case).
    shore, port = shore_run.start_shore(shore_bin, root, sil_work, ("--resume", "--linger", "10", "--fetch", "*.sbd"))
    procs.append(shore)
    # glider-plant's defaults in the HIL run: seed 1, heading 90, depth rating 100 m, the default launch point.
    sil = subprocess.Popen([glider_sil, mi, "--vehicle", os.path.join(source, "boards/vehicles/slocum_we01.toml"),
                            "--seed", "1", "--heading-deg", "90", "--max-working-depth-m", "100",
                            "--max-sim-time-s", "4500", "--vehicle-name", NAME, "--shore", "127.0.0.1:" + port,
                            "--slocum-dir", slocum, "--time-scale", str(SIL_TIME_SCALE)], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    procs.append(sil)
    logs = os.path.join(root, NAME, "logs")
    queued_goto = queued_broken = None
    deadline = time.monotonic() + 25
    while sil.poll() is None and time.monotonic() < deadline:
        n = len(glob.glob(os.path.join(logs, "*.surfacing.json")))
        if queued_goto is None and n >= 1:
            subprocess.run([shore_bin, "queue", "--root", root, NAME, goto], check=True)
            queued_goto = n
        elif queued_broken is None and queued_goto is not None and n > queued_goto and \
                glob.glob(os.path.join(root, NAME, "to-glider/sent/*goto_l10.ma")):
            subprocess.run([shore_bin, "queue", "--root", root, NAME, broken], check=True)
            queued_broken = n
        time.sleep(0.005)
    if sil.poll() is None:
        sil.kill()
    sil_out = sil.communicate()[0]
    shore.terminate()
    shore.communicate(timeout=10)
    check(sil.returncode == 0, "glider-sil completed the mission by itself (exit %s)" % sil.returncode)
    if sil.returncode != 0:
        print(sil_out[-2000:])

    h_events, h_journals = shore_run.events_of(os.path.join(hil_keep, "shore"), NAME)
    s_events, s_journals = shore_run.events_of(root, NAME)
    check(len(h_events) >= 5 and len(s_events) >= 1, "calls: HIL %d, SIL %d" % (len(h_events), len(s_events)))
    if failures:
        sys.exit(1)
    h, s = summary(h_events, h_journals), summary(s_events, s_journals)
    print("call  HIL: MT since launch call, fix (deg), .sbd (mission, segment) | SIL: the same | fix apart")
    for k in range(max(len(h), len(s))):
        a = h[k] if k < len(h) else None
        b = s[k] if k < len(s) else None
        fmt = lambda c: "%7.0f s %.5f %.5f %s%s%s" % (c["t"], c["fix"][0], c["fix"][1], c["sbd"],
                                                     " accepted" if c["accepted"] else "",
                                                     " refused" if c["refused"] else "") if c else "-"
        apart = "%.0f m" % distance_m(a["fix"], b["fix"]) if a and b else ""
        print("%4d  %s | %s | %s" % (k, fmt(a), fmt(b), apart))
    check(len(h) == len(s), "the same number of calls (HIL %d, SIL %d)" % (len(h), len(s)))
    check([c["accepted"] for c in h] == [c["accepted"] for c in s], "the goto accepted in the same call")
    check([c["refused"] for c in h] == [c["refused"] for c in s], "the truncated upload refused in the same call")
    check([c["sbd"] for c in h] == [c["sbd"] for c in s], "the same .sbd segments received in the same calls")
    for k, (a, b) in enumerate(zip(h, s)):
        tol = GPS_TOL_M + k * PER_DIVE_TOL_M
        check(distance_m(a["fix"], b["fix"]) <= tol, "call %d: fixes %.1f m apart (within %.1f m: GPS %.1f + %d "
              "dives x %.0f)" % (k, distance_m(a["fix"], b["fix"]), tol, GPS_TOL_M, k, PER_DIVE_TOL_M))
    h_sbd = sorted(glob.glob(os.path.join(hil_keep, "shore", NAME, "from-glider", "*.sbd")))
    s_sbd = sorted(glob.glob(os.path.join(root, NAME, "from-glider", "*.sbd")))
    for a, b in zip(h_sbd, s_sbd):
        ha, hb = header_of(a), header_of(b)
        same = all(ha.get(k) == hb.get(k) and ha.get(k) for k in ("sensor_list_crc", "sensors_per_cycle"))
        check(same, "%s / %s: the same sensor list (crc %s, %s sensors)" % (
            os.path.basename(a), os.path.basename(b), ha.get("sensor_list_crc"), ha.get("sensors_per_cycle")))
finally:
    for p in procs:
        if p.poll() is None:
            p.kill()
    if os.environ.get("E2E_KEEP"):
        shutil.copytree(work, os.environ["E2E_KEEP"], dirs_exist_ok=True, symlinks=True)
    shutil.rmtree(work, ignore_errors=True)
print("PASS" if not failures else "FAILED: %d" % len(failures))
sys.exit(0 if not failures else 1)
