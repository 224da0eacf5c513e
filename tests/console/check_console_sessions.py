#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Console logins survive a restart of the shore (docs/console.md, "Security
model", sessions): with the login forced on loopback (--http-auth), a pilot's
session cookie and CSRF token still work after the shore is stopped and
started again; the sessions file (ROOT/console.sessions) is mode 0600 and
holds the cookie only as its SHA-256; a logout, an expiry, an account whose
role changed and a damaged file each end the sessions they concern, and the
shore says why for a damaged file (file named) and starts with nobody logged in.
Usage: check_console_sessions.py GLIDER_SHORE WORK_DIR. Exit 0 = pass."""
import hashlib
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import console_harness as h  # noqa: E402
import fake_events  # noqa: E402

shore_bin, work = sys.argv[1:3]
h.fresh_dir(work)
root = os.path.join(work, "root")
users = os.path.join(work, "console.users")
sessions_file = os.path.join(root, "console.sessions")
fake_events.write_call(root, "g1", 60, 1)
for name, role, password in (("pilot1", "pilot", "correct horse battery"), ("pilot2", "pilot", "second pilot pass"),
                             ("viewer1", "viewer", "viewer password 1")):
    r = subprocess.run([shore_bin, "user", "add", name, "--role", role, "--users", users], input=password + "\n",
                       capture_output=True, text=True, timeout=30)
    h.check(r.returncode == 0, "user add %s" % name)


def start(ttl="3600"):
    return h.Shore(shore_bin, work, ["--http-auth", "--users", users, "--session-ttl", ttl])


def login(shore, user, password):
    body, ctype = h.multipart({"user": user, "password": password})
    status, headers, data = h.request(shore.port, "POST", "/api/login", body, {"Content-Type": ctype})
    return status, headers.get("set-cookie", "").split(";")[0], (json.loads(data) if status == 200 else None)


def session(shore, cookie):
    return h.get_json(shore.port, "/api/session", {"Cookie": cookie})


def command(shore, cookie, csrf, text):
    body, ctype = h.multipart({"command": text})
    return h.request(shore.port, "POST", "/api/gliders/g1/command", body,
                     {"Content-Type": ctype, "Cookie": cookie, "X-CSRF-Token": csrf})[0]


shore = start()
try:
    status, pilot, info = login(shore, "pilot1", "correct horse battery")
    h.check(status == 200 and pilot.startswith("glider_session="), "pilot1 logged in (%d)" % status)
    status, viewer, _ = login(shore, "viewer1", "viewer password 1")
    status2, other, _ = login(shore, "pilot2", "second pilot pass")
    h.check(status == 200 and status2 == 200, "viewer1 and pilot2 logged in")
    csrf = session(shore, pilot)[1]["csrf"]
finally:
    shore.stop()

token = pilot.split("=", 1)[1]
text = open(sessions_file).read()
saved = json.loads(text)
h.check(oct(os.stat(sessions_file).st_mode & 0o777) == "0o600", "the sessions file is mode 0600")
h.check(saved["schema"] == "glider-console-sessions/1" and len(saved["sessions"]) == 3,
        "the sessions file holds the 3 logins")
h.check(token not in text and hashlib.sha256(token.encode()).hexdigest() in text,
        "it holds the cookie only as its SHA-256")

shore = start()
try:
    status, s = session(shore, pilot)
    h.check(status == 200 and s["user"] == "pilot1" and s["role"] == "pilot" and s["csrf"] == csrf,
            "after a restart pilot1's cookie is still logged in, same CSRF token (%d)" % status)
    h.check(command(shore, pilot, csrf, "report ++ m_depth") == 200, "and may act with it (a command queued)")
    h.check(command(shore, pilot, "0" * 64, "report ++ m_pitch") == 403, "another CSRF token is still refused")
    status, s = session(shore, viewer)
    h.check(status == 200 and s["role"] == "viewer", "viewer1 still logged in as a viewer")
    body, ctype = h.multipart({"bye": "1"})
    other_csrf = session(shore, other)[1]["csrf"]
    status = h.request(shore.port, "POST", "/api/logout", body,
                       {"Content-Type": ctype, "Cookie": other, "X-CSRF-Token": other_csrf})[0]
    h.check(status == 200 and session(shore, other)[0] == 401, "pilot2 logged out (%d)" % status)
finally:
    shore.stop()

# viewer1 becomes a pilot: a session of the old role must not carry over.
r = subprocess.run([shore_bin, "user", "add", "viewer1", "--role", "pilot", "--users", users],
                   input="viewer password 1\n", capture_output=True, text=True, timeout=30)
shore = start()
try:
    h.check(session(shore, other)[0] == 401, "after a restart the logged-out session stays out")
    h.check(session(shore, viewer)[0] == 401, "a session of an account whose role changed ends at the restart")
    h.check(session(shore, pilot)[0] == 200, "pilot1 still in")
finally:
    shore.stop()
h.check(len(json.load(open(sessions_file))["sessions"]) == 1, "the file keeps pilot1's session only")

# A shorter --session-ttl at the restart cuts longer logins; an expired one is gone.
# 6 s, not 2: a scrypt login and the check after it take seconds at load ~20.
shore = start("6")
try:
    h.check(session(shore, pilot)[0] == 401, "restarted with --session-ttl 6: the 1 h login is not kept")
    status, short, _ = login(shore, "pilot1", "correct horse battery")
    short_at = time.time()
    h.check(status == 200 and session(shore, short)[0] == 200, "a new 6 s login")
finally:
    shore.stop()
time.sleep(max(0.0, short_at + 6.5 - time.time()))
shore = start("6")
try:
    h.check(session(shore, short)[0] == 401, "expired while the shore was down: logged out after the restart")
finally:
    shore.stop()
h.check(json.load(open(sessions_file))["sessions"] == [], "the file is emptied of the expired login")

# A damaged file: nobody stays logged in, the shore says which file and why, and runs.
for damage in ('{"schema": "glider-console-sessions/1", "sessions": [{"user": "pilot1"}]}', "not json {"):
    open(sessions_file, "w").write(damage)
    shore = start()
    try:
        status, s = session(shore, short)
        log = open(shore.log_path).read()
    finally:
        shore.stop()
    h.check(status == 401 and sessions_file in log and "nobody stays logged in" in log,
            "a damaged file (%s): nobody logged in, named in the shore's output: %s" %
            (damage[:20], [l for l in log.splitlines() if "console.sessions" in l][:1]))
    h.check(json.load(open(sessions_file))["sessions"] == [], "and rewritten empty")
h.finish()
