#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""End to end in SIL: glider-sil --shore --slocum-dir against a real
glider-shore serve on loopback (ephemeral port from --port-file).

A Slocum mission (box_current, the keystroke wait made 300 s so the shore
has time to work) with at least three surfacings after the launch call:
- every call gets one surfacing event naming the glider, with its fix;
- every closed .sbd the vehicle wrote arrives in from-glider/, byte-equal
  to the vehicle's file (the vehicle's own Zmodem sender, the shore's rz);
- a goto .ma queued (glider-shore queue) once the first event is written
  is received by the vehicle's Zmodem receiver (zr, the shore's sz),
  validated as at launch and flown: the fixes after it close on its
  waypoint, which the old box never goes near;
- a truncated .ma queued after that is refused, the refusal (file:line)
  is in the dialog the shore journals, and the goto plan is kept.
Usage: check_sil_e2e.py GLIDER_SIL GLIDER_SHORE SOURCE_DIR. Exit 0 = pass."""
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../comms"))
import shore_run  # noqa: E402

glider_sil, glider_shore, source = sys.argv[1:4]
# SIL runs lockstep with the shore's answers during a call; between calls it
# is paced at this many simulated seconds per wall second, so that the
# pilot's queue (this script, reacting to an event) lands before the next
# call: ~2000 s between surfacings = 2 s of wall time.
TIME_SCALE = 1000
NAME = "unit_345"
# The new waypoint: 3.3 km south-west of the launch point, away from the box (north-east of it).
NEW_WPT = (5417.9000, 722.0000)  # DDMM.MMMM lat, lon
check = shore_run.Checks()
failures = check.failures


def ddmm_to_deg(v):
    sign = -1.0 if v < 0 else 1.0
    v = abs(v)
    d = math.floor(v / 100.0)
    return sign * (d + (v - 100.0 * d) / 60.0)


def distance_m(lat1, lon1, lat2, lon2):
    k = math.pi / 180.0
    x = (lon2 - lon1) * k * math.cos(0.5 * (lat1 + lat2) * k)
    return 6371000.0 * math.hypot(x, (lat2 - lat1) * k)


work = tempfile.mkdtemp(prefix="sil_e2e_")
try:
    mission = os.path.join(work, "mission")
    shutil.copytree(os.path.join(source, "boards/missions/box_current"), mission)
    surfac = os.path.join(mission, "mafiles/surfac10.ma")
    text = open(surfac).read()
    text = text.replace("b_arg: end_action(enum)          2   # resume",
                        "b_arg: end_action(enum)          1   # wait for the pilot, then resume\n"
                        "    b_arg: keystroke_wait_time(s)  300")
    assert "keystroke_wait_time" in text
    open(surfac, "w").write(text)
    # The pilot's goto: one waypoint, south-west of the launch point.
    goto = os.path.join(work, "goto_l10.ma")
    open(goto, "w").write(
        "behavior_name=goto_list\n<start:b_arg>\n"
        "    b_arg: start_when(enum)          0\n"
        "    b_arg: list_stop_when(enum)      7\n"
        "    b_arg: list_when_wpt_dist(m)   150\n"
        "    b_arg: initial_wpt(enum)        -1\n"
        "    b_arg: num_waypoints(nodim)      1\n"
        "    b_arg: num_legs_to_run(nodim)   -2\n"
        "<end:b_arg>\n<start:waypoints>\n"
        f"{NEW_WPT[1]:.4f} {NEW_WPT[0]:.4f}\n"
        "<end:waypoints>\n")
    # A cut upload: the file ends in its argument block.
    broken_dir = os.path.join(work, "broken")
    os.makedirs(broken_dir)
    broken = os.path.join(broken_dir, "goto_l10.ma")
    open(broken, "w").write(open(goto).read().split("<end:b_arg>")[0])

    root = os.path.join(work, "shore")
    slocum = os.path.join(work, "slocum")
    shore, port = shore_run.start_shore(glider_shore, root, work)
    sil = subprocess.Popen(
        [glider_sil, os.path.join(mission, "missions/box.mi"),
         "--vehicle", os.path.join(source, "boards/vehicles/slocum_we01.toml"),
         "--max-sim-time-s", "9500", "--vehicle-name", NAME, "--shore", f"127.0.0.1:{port}",
         "--slocum-dir", slocum, "--time-scale", str(TIME_SCALE)],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    logs = os.path.join(root, NAME, "logs")
    queued_goto = queued_broken = None
    deadline = time.time() + 45
    while sil.poll() is None and time.time() < deadline:
        events = sorted(glob.glob(os.path.join(logs, "*.surfacing.json")))
        if queued_goto is None and events:
            subprocess.run([glider_shore, "queue", "--root", root, NAME, goto], check=True)
            queued_goto = len(events)
        elif queued_broken is None and queued_goto is not None:
            # Once the goto went out (moved to to-glider/sent/) and that call's event is written.
            sent = glob.glob(os.path.join(root, NAME, "to-glider/sent/*goto_l10.ma"))
            if sent and len(events) > queued_goto:
                subprocess.run([glider_shore, "queue", "--root", root, NAME, broken], check=True)
                queued_broken = len(events)
        time.sleep(0.02)
    if sil.poll() is None:
        sil.kill()
    sil_out = sil.communicate()[0]
    shore.terminate()
    shore_out = shore.communicate(timeout=10)[0]
    # 3: stopped by --max-sim-time-s (README exit codes), the box not finished: expected.
    ran = sil.returncode == 3 and "NOT complete (time limit)" in sil_out
    check(ran, f"glider-sil flew until its time limit (exit {sil.returncode})")
    if not ran:
        print(sil_out[-3000:])
    print(shore_out[-1500:])

    events = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(logs, "*.surfacing.json")))]
    journals = sorted(glob.glob(os.path.join(logs, "*.journal")))
    print(f"{len(events)} calls, goto queued after call {queued_goto}, broken .ma after call {queued_broken}")
    check(len(events) >= 4, f"a launch call and at least three surfacings called (got {len(events)} events)")
    check(len(journals) == len(events), "one journal per event")
    for e in events:
        check(e["glider"] == NAME and e["gps"] is not None and e["prompt"] is not None,
              f"event {e['journal']}: glider, fix, prompt ({e['end_reason']})")
    check(all(e["end_reason"] == "hangup" for e in events), "every call ended by the glider hanging up")

    # Every closed .sbd the vehicle wrote, equal at the shore.
    # (sent ones moved to sentlogs/ by the vehicle: docs/comms.md, End to end)
    vehicle_sbd = sorted(glob.glob(os.path.join(slocum, "*.sbd")) + glob.glob(os.path.join(slocum, "sentlogs", "*.sbd")),
                         key=os.path.basename)
    received = sorted(glob.glob(os.path.join(root, NAME, "from-glider", "*.sbd")))
    names = {os.path.basename(p) for p in received}
    # The last segment is still open at the last call (it holds that surfacing).
    expected = [p for p in vehicle_sbd[:-1]]
    check(len(expected) >= 3, f"the vehicle closed at least three .sbd ({len(expected)})")
    for p in expected:
        name = os.path.basename(p)
        same = name in names and open(p, "rb").read() == open(
            os.path.join(root, NAME, "from-glider", name), "rb").read()
        check(same, f"{name} received equal to the vehicle's ({os.path.getsize(p)} bytes)")
        check(os.path.exists(os.path.join(root, NAME, "from-glider", name + ".csv")), f"{name}.csv converted")
    check(not glob.glob(os.path.join(root, NAME, ".incoming", "*")), "nothing left half received")
    # What was sent is not sent again: each file crosses the link in one call only.
    got = [f["name"] for e in events for f in e["files_received"]]
    check(len(got) == len(set(got)) and all(f["status"] == "new" for e in events for f in e["files_received"]),
          f"no file received twice ({len(got)} receptions, {len(set(got))} files)")
    check([os.path.basename(p) for p in glob.glob(os.path.join(slocum, "*.sbd"))] == [os.path.basename(vehicle_sbd[-1])],
          "on the vehicle only the open segment is left unsent; the rest in sentlogs/")

    # The goto: delivered, accepted, flown.
    text = "\n".join(open(j).read() for j in journals)
    check(text.count("goto_l10.ma accepted") == 1, "the vehicle accepted the uploaded goto_l10.ma, once")
    check(text.count("goto_l10.ma refused (the old plan is flown)") == 1, "the truncated .ma refused once")
    accepted = next(i for i, j in enumerate(journals) if "goto_l10.ma accepted" in open(j).read()) \
        if "goto_l10.ma accepted" in text else None
    if accepted is not None:
        fixes = [(e["gps"]["lat_deg"], e["gps"]["lon_deg"]) for e in events[accepted:]]
        wlat, wlon = ddmm_to_deg(NEW_WPT[0]), ddmm_to_deg(NEW_WPT[1])
        dist = [distance_m(la, lo, wlat, wlon) for la, lo in fixes]
        print("distance to the new waypoint at each fix from the accepting call on:",
              " ".join(f"{d:.0f}" for d in dist), "m")
        check(len(dist) >= 2 and all(b < a - 300.0 for a, b in zip(dist, dist[1:])),
              "each later fix is > 300 m nearer the new waypoint")
    # The broken upload: refused, said in the dialog, the goto kept.
    check(queued_broken is not None, "the truncated .ma was queued before the mission ended")
    check("goto_l10.ma refused (the old plan is flown)" in text, "the truncated upload was refused at once")
    refusal_lines = [l for l in text.splitlines() if "< goto_l10.ma refused: " in l]
    check(bool(refusal_lines), "the refusal is in a later dialog")
    if refusal_lines:
        print("refusal in the dialog:", refusal_lines[0])
        check("goto_l10.ma:" in refusal_lines[0], "the refusal names the received file and its line")
    check(open(os.path.join(mission, "mafiles/goto_l10.ma")).read() == open(goto).read(),
          "the mission's goto_l10.ma is the accepted one (the refused file did not replace it)")
finally:
    # E2E_KEEP=DIR keeps the shore's folders (the journals quoted in docs/comms.md).
    if os.environ.get("E2E_KEEP"):
        shutil.copytree(os.path.join(work, "shore"), os.environ["E2E_KEEP"], dirs_exist_ok=True)
    shutil.rmtree(work, ignore_errors=True)
print("PASS" if not failures else f"FAILED: {len(failures)}")
sys.exit(0 if not failures else 1)
