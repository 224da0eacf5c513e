#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Every call delivers the segment its surfacing closed, also when the
surface behaviour does not wait for a keystroke.

boards/missions/box_current as shipped: its every-30-min surface has
end_action 2 (resume), so keystroke_wait_time is 0. glider-sil --shore
against a real glider-shore serve --resume, as fast as the lockstep with the
shore allows (no --time-scale). The shore types `whoru`, then `send *.sbd
*.tbd` on the next prompt; before the fix the glider resumed the mission on
the `whoru` answer and hung up on the `send` (4 calls, 0 files). Now a shore
that has typed gets the reply window (CommsConfig::reply_window_s) for its
next line. Checked per call: the launch call receives nothing (no segment
closed yet); call k (k >= 1) receives exactly segment k-1, once, byte-equal to
the vehicle's copy in sentlogs/; only the open segment stays unsent.
Usage: check_sil_files_per_call.py GLIDER_SIL GLIDER_SHORE SOURCE_DIR. Exit 0 = pass."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../comms"))
import shore_run  # noqa: E402

glider_sil, shore_bin, source = sys.argv[1:4]
NAME = "g00"
check = shore_run.Checks()
work = tempfile.mkdtemp(prefix="sil_files_per_call_")
try:
    surfac = open(os.path.join(source, "boards/missions/box_current/mafiles/surfac10.ma")).read()
    assert "end_action(enum)          2" in surfac and "keystroke_wait_time" not in surfac, "the test's premise"
    root = os.path.join(work, "shore")
    slocum = os.path.join(work, "slocum")
    shore, port = shore_run.start_shore(shore_bin, root, work)
    run = subprocess.run(
        [glider_sil, os.path.join(source, "boards/missions/box_current/missions/box.mi"),
         "--vehicle", os.path.join(source, "boards/vehicles/slocum_we01.toml"), "--max-sim-time-s", "8000",
         "--vehicle-name", NAME, "--shore", f"127.0.0.1:{port}", "--slocum-dir", slocum],
        capture_output=True, text=True, timeout=45)
    print(shore_run.stop_shore(shore)[-800:])
    check(run.returncode == 3 and "NOT complete (time limit)" in run.stdout,
          f"glider-sil flew until its time limit (exit {run.returncode})")
    events, journals = shore_run.events_of(root, NAME)
    per_call = [[f["name"] for f in e["files_received"]] for e in events]
    for i, (e, names) in enumerate(zip(events, per_call)):
        print(f"call {i}: MT {e['glider_time']['mission_time_s']:6.0f} s, {e['end_reason']}, received {names}")
    check(len(events) >= 5, f"the launch call and at least four surfacings called ({len(events)} events)")
    check(per_call[:1] == [[]], "the launch call: no segment closed yet, none received")
    for k in range(1, len(events)):
        expected = [f for f in sorted(os.listdir(os.path.join(slocum, "sentlogs")))
                    if shore_run.segment_of(f) == (0, k - 1)]
        check(per_call[k] == expected and len(expected) == 1,
              f"call {k}: exactly segment 00-{k - 1:03d}.sbd, the one its surfacing closed (got {per_call[k]})")
    received = [n for names in per_call for n in names]
    check(len(received) == len(set(received)), "no file received twice")
    for n in received:
        got = open(os.path.join(root, NAME, "from-glider", n), "rb").read()
        check(got == open(os.path.join(slocum, "sentlogs", n), "rb").read(), f"{n} byte-equal to the vehicle's")
    unsent = sorted(f for f in os.listdir(slocum) if f.endswith(".sbd"))
    check(len(unsent) == 1 and shore_run.segment_of(unsent[0]) == (0, len(events) - 1),
          f"only the open segment is left unsent on the vehicle ({unsent})")
finally:
    if os.environ.get("E2E_KEEP"):
        shutil.copytree(work, os.environ["E2E_KEEP"], dirs_exist_ok=True)
    shutil.rmtree(work, ignore_errors=True)
sys.exit(1 if check.failures else 0)
