#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil --shore against a minimal shore on loopback TCP: the vehicle
calls, the shore sees the surface dialog, types `whoru` and gets the answer.
Usage: check_sil_shore.py GLIDER_SIL SOURCE_DIR. Exit 0 = pass."""
import socket
import subprocess
import sys
import threading
import time

glider_sil, source = sys.argv[1], sys.argv[2]
server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
server.bind(("127.0.0.1", 0))
server.listen(4)
server.settimeout(0.2)
stop = threading.Event()
port = server.getsockname()[1]
transcript = bytearray()
calls = []


def shore():
    try:
        while not stop.is_set():
            try:
                conn, _ = server.accept()
            except socket.timeout:
                continue
            calls.append(time.time())
            conn.settimeout(0.2)
            asked = False
            with conn:
                while True:
                    try:
                        data = conn.recv(4096)
                    except socket.timeout:
                        if stop.is_set():
                            break
                        continue
                    if not data:
                        break
                    transcript.extend(data)
                    if not asked and b"Vehicle Name:" in transcript:
                        conn.sendall(b"whoru\r")
                        asked = True
    except (socket.timeout, OSError):
        pass


thread = threading.Thread(target=shore, daemon=True)
thread.start()
run = subprocess.run(
    [glider_sil, "--mission", f"{source}/boards/missions/box_current/missions/box.mi",
     "--vehicle", f"{source}/boards/vehicles/slocum_we01.toml", "--max-sim-time-s", "900",
     "--vehicle-name", "unit_345", "--shore", f"127.0.0.1:{port}"],
    capture_output=True, text=True, timeout=50)
stop.set()
thread.join(5)
server.close()
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
