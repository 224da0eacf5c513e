#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil --shore against a minimal shore on loopback TCP: the vehicle
calls, the shore sees the surface dialog, types `whoru` and gets the answer.
Usage: check_sil_shore.py GLIDER_SIL SOURCE_DIR. Exit 0 = pass."""
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from shore_run import TcpShore  # noqa: E402

glider_sil, source = sys.argv[1], sys.argv[2]


def answer(conn, transcript, state):
    """Types `whoru` once the dialog named the vehicle."""
    if not state.get("asked") and b"Vehicle Name:" in transcript:
        conn.sendall(b"whoru\r")
        state["asked"] = True


shore = TcpShore(answer)
port = shore.port
run = subprocess.run(
    [glider_sil, "--mission", f"{source}/boards/missions/box_current/missions/box.mi",
     "--vehicle", f"{source}/boards/vehicles/slocum_we01.toml", "--max-sim-time-s", "900",
     "--vehicle-name", "unit_345", "--shore", f"127.0.0.1:{port}"],
    capture_output=True, text=True, timeout=50)
shore.stop()
calls, transcript = shore.calls, shore.transcript
text = transcript.decode("latin-1")
first = text.find("Glider ")
print(text[first:text.find("Hit Control-W", first) + 40] if first >= 0 else text[:2000])
print(run.stdout)
print(run.stderr, file=sys.stderr)
checks = {
    "a call reached the shore": len(calls) >= 1,
    "surfacing line": "Glider unit_345 at surface.\r\n" in text,
    "Vehicle Name": "Vehicle Name: unit_345\r\n" in text,
    "GPS Location": "GPS Location:" in text,
    "ABORT HISTORY": "ABORT HISTORY: total since reset: 0\r\n" in text,
    "glider-sil reports the calls": "calls connected" in run.stdout,
}
for name, ok in checks.items():
    print(("ok   " if ok else "FAIL ") + name)
print(f"{len(calls)} call(s), {len(transcript)} bytes from the vehicle")
sys.exit(0 if all(checks.values()) else 1)
