# SPDX-License-Identifier: Apache-2.0
"""What the end-to-end comms tests share: a check list, a real glider-shore
on an ephemeral loopback port, and the events and journals it wrote
(docs/comms.md, End to end). Imported by the check_*.py scripts beside it."""
import glob
import json
import os
import re
import subprocess
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


def start_shore(shore_bin, root, work, extra=()):
    """glider-shore serve on 127.0.0.1, port 0; returns (process, port) once the port file is written."""
    port_file = os.path.join(work, "shore.port")
    shore = subprocess.Popen(
        [shore_bin, "serve", "--root", root, "--port", "0", "--port-file", port_file, "--resume",
         "--linger", "20", "--identify-timeout", "20", "--prompt-timeout", "20", "--transfer-idle-timeout", "20",
         *extra], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.time() + 10
    while not os.path.exists(port_file) and time.time() < deadline and shore.poll() is None:
        time.sleep(0.02)
    if not os.path.exists(port_file):
        shore.kill()
        raise RuntimeError("glider-shore wrote no port file: " + shore.communicate()[0][-2000:])
    return shore, int(open(port_file).read().strip())


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
