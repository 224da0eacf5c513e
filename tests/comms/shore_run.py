# SPDX-License-Identifier: Apache-2.0
"""What the comms tests' scripts share (tests/comms, tests/comms_e2e): a
check list, a real glider-shore on an ephemeral loopback port and the events
and journals it wrote (docs/comms.md, End to end), and a minimal in-script
shore on loopback TCP (TcpShore) for glider-sil --shore."""
import glob
import json
import os
import re
import socket
import subprocess
import threading
import time


class Checks:
    """`check(ok, what)` prints ok/FAIL and remembers the failures."""

    def __init__(self):
        self.failures = []

    def __call__(self, ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            self.failures.append(what)
        return ok


# The SIL tests' shore: resumes the mission, short waits (a test's calls are quick).
QUICK = ("--resume", "--linger", "20", "--identify-timeout", "20", "--prompt-timeout", "20",
         "--transfer-idle-timeout", "20")


def start_shore(shore_bin, root, work, options=QUICK):
    """glider-shore serve on 127.0.0.1, port 0, with `options`; returns (process, "PORT") once the port file
    is written."""
    port_file = os.path.join(work, "shore.port")
    shore = subprocess.Popen([shore_bin, "serve", "--root", root, "--port", "0", "--port-file", port_file, *options],
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 10
    while not os.path.exists(port_file) and time.time() < deadline and shore.poll() is None:
        time.sleep(0.02)
    if not os.path.exists(port_file):
        shore.kill()
        raise RuntimeError("glider-shore wrote no port file: " + shore.communicate()[0][-2000:])
    return shore, open(port_file).read().strip()


def stop_shore(shore):
    """SIGTERM (calls end, journals and events written), then its output."""
    if shore.poll() is None:
        shore.terminate()
    return shore.communicate(timeout=10)[0]


def events_of(root, glider):
    """The glider's surfacing events and journals, oldest first."""
    logs = os.path.join(root, glider, "logs")
    return ([json.load(open(p)) for p in sorted(glob.glob(os.path.join(logs, "*.surfacing.json")))],
            [open(j).read() for j in sorted(glob.glob(os.path.join(logs, "*.journal")))])


def segment_of(name):
    """(mission, segment) of a Slocum segment file name NAME-YYYY-DDD-M-S.sbd, else None."""
    m = re.match(r"^(.+)-(\d{4})-(\d{3})-(\d+)-(\d+)\.sbd$", name)
    return (int(m.group(4)), int(m.group(5))) if m else None


class TcpShore:
    """`answer(conn, transcript)` runs after each chunk the vehicle sends, with the transcript so far
    (a bytearray, all calls); it may `conn.sendall(...)`. A fresh `state` dict is passed per call."""

    def __init__(self, answer, poll_s=0.2):
        self.answer = answer
        self.poll_s = poll_s
        self.transcript = bytearray()
        self.calls = []  # wall time of each call's start
        self._stop = threading.Event()
        self._server = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        self._server.bind(("127.0.0.1", 0))
        self._server.listen(4)
        self._server.settimeout(0.2)
        self.port = self._server.getsockname()[1]
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()

    def _serve(self):
        try:
            while not self._stop.is_set():
                try:
                    conn, _ = self._server.accept()
                except socket.timeout:
                    continue
                self.calls.append(time.time())
                conn.settimeout(self.poll_s)
                state = {}
                with conn:
                    while True:
                        try:
                            data = conn.recv(4096)
                        except socket.timeout:
                            if self._stop.is_set():
                                break
                            continue
                        if not data:
                            break
                        self.transcript.extend(data)
                        self.answer(conn, self.transcript, state)
        except OSError:
            pass

    def stop(self):
        self._stop.set()
        self._thread.join(5)
        self._server.close()
