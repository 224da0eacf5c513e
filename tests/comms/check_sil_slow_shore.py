#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil --shore against a shore that thinks in wall time: SIL's clock
must not run on while the shore works (docs/comms.md, End to end: the
lockstep with a real shore).

The shore sets the glider's keystroke wait to 20 s (`!put`), then waits
1.5 s of wall time before each of `whoru`, `!get u_keystroke_wait_time` and
Control-R, as a loaded shore station or a slow pilot's script would. If SIL's
simulated time ran on meanwhile (before the fix it waited at most 20 ms of
wall time a cycle for the shore: 1.5 s = 75 simulated seconds), the glider
would hang up after its 20 s keystroke wait before the first of them. In
lockstep, every answer reaches the glider in the same call, within the
keystroke wait.
Usage: check_sil_slow_shore.py GLIDER_SIL SOURCE_DIR. Exit 0 = pass."""
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shore_run import TcpShore  # noqa: E402

glider_sil, source = sys.argv[1], sys.argv[2]
THINK_S = 1.5
PROMPT = re.compile(rb"GliderDos [INA] -?\d+ >$")
SCRIPT = [(0.0, b"!put u_keystroke_wait_time 20\r"), (THINK_S, b"whoru\r"),
          (THINK_S, b"!get u_keystroke_wait_time\r"), (THINK_S, b"\x12")]


def answer(conn, transcript, state):
    """One line per prompt, after the shore's thinking time."""
    step = state.get("step", 0)
    if step < len(SCRIPT) and PROMPT.search(bytes(transcript).rstrip(b" ")):
        time.sleep(SCRIPT[step][0])
        conn.sendall(SCRIPT[step][1])
        state["step"] = step + 1


shore = TcpShore(answer, poll_s=0.05)
port = shore.port
started = time.monotonic()
run = subprocess.run(
    [glider_sil, "--mission", f"{source}/boards/missions/box_current/missions/box.mi",
     "--vehicle", f"{source}/boards/vehicles/slocum_we01.toml", "--max-sim-time-s", "900",
     "--vehicle-name", "unit_345", "--shore", f"127.0.0.1:{port}"],
    capture_output=True, text=True, timeout=50)
wall_s = time.monotonic() - started
shore.stop()
calls, transcript = shore.calls, shore.transcript
text = transcript.decode("latin-1")
print(text[text.find("GliderDos"):][:1500])
print(run.stdout)
print(run.stderr, file=sys.stderr)
pacing = re.search(r"shore pacing\s*: (\d+) waits for the shore's answer, (\d+) unanswered", run.stdout)
checks = {
    "one call": len(calls) == 1,
    "the keystroke wait was put to 20 s": "!put u_keystroke_wait_time 20\r\nu_keystroke_wait_time(s)=20" in text,
    "whoru answered after the shore's 1.5 s": "Vehicle Name: unit_345\r\nGliderDos" in text.split("whoru\r\n", 1)[-1],
    "get answered after 3 s": "!get u_keystroke_wait_time\r\nu_keystroke_wait_time(s)=20" in text,
    "Control-R reached the glider in the same call": "Resuming the mission" in text,
    "glider-sil reports its waits for the shore, each answered": pacing is not None and int(pacing.group(1)) >= 3,
}
for name, ok in checks.items():
    print(("ok   " if ok else "FAIL ") + name)
print(f"{len(calls)} call(s), {len(transcript)} bytes from the vehicle, {wall_s:.1f} s wall")
sys.exit(0 if all(checks.values()) else 1)
