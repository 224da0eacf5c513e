#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The console's security model (docs/console.md, "Security"), with the login
forced on loopback (--http-auth: what any other address gets) and raw HTTP
requests: off loopback without a users file the shore refuses to start;
unauthenticated, wrong-role, CSRF-less, path-traversal, oversized and
malformed requests are all refused; passwords are scrypt hashes; sessions
expire and end at logout; wrong passwords lock the user out for a minute;
without a login (loopback) a foreign Host and a missing CSRF token are still
refused. Rehearsals (a fixture standing in for glider-forecast) gate the
queue, and an override is explicit and journaled.
Usage: check_console_security.py GLIDER_SHORE SOURCE_DIR WORK_DIR. Exit 0 = pass."""
import json
import os
import shutil
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import console_harness as h  # noqa: E402
import fake_events  # noqa: E402

shore_bin, source, work = sys.argv[1:4]
h.fresh_dir(work)


root = os.path.join(work, "root")
users = os.path.join(work, "console.users")
fake_events.write_call(root, "g1", 60, 1)

# Off loopback with no users file: refused before anything listens.
r = subprocess.run([shore_bin, "serve", "--root", root, "--port", "0", "--http", "0.0.0.0:0", "--users", users],
                   capture_output=True, text=True, timeout=20)
h.check(r.returncode == 2 and "off loopback" in r.stderr, "off loopback without users: exit 2 (%d: %s)" %
      (r.returncode, r.stderr.strip()[:160]))
for http, why in (("localhost:8080", "is not an IPv4 or IPv6 address"), ("127.0.0.1:65536", "outside the allowed range"),
                  ("127.0.0.1", "give ADDR:PORT")):
    r = subprocess.run([shore_bin, "serve", "--root", root, "--port", "0", "--http", http], capture_output=True,
                       text=True, timeout=20)
    h.check(r.returncode == 2 and why in r.stderr, "--http %s: exit 2, %s (%d)" % (http, why, r.returncode))
for name, role, password in (("pilot1", "pilot", "correct horse battery"), ("viewer1", "viewer", "viewer password 1")):
    r = subprocess.run([shore_bin, "user", "add", name, "--role", role, "--users", users], input=password + "\n",
                       capture_output=True, text=True, timeout=30)
    h.check(r.returncode == 0, "user add %s (%s)" % (name, r.stdout.strip() or r.stderr.strip()))
text = open(users).read()
h.check("correct horse" not in text and text.count(":scrypt$131072$8$1$") == 2, "the users file holds scrypt hashes only")
h.check(oct(os.stat(users).st_mode & 0o777) == "0o600", "the users file is mode 0600")
r = subprocess.run([shore_bin, "user", "add", "x", "--role", "pilot", "--users", users], input="short\n",
                   capture_output=True, text=True, timeout=30)
h.check(r.returncode == 1 and "allowed 8-1024" in r.stderr, "a short password is refused (%s)" % r.stderr.strip())

shore = h.Shore(shore_bin, work, ["--http-auth", "--users", users, "--max-upload", "4096", "--session-ttl", "30",
                                  "--forecast-program", os.path.join(here, "fake_rehearse.py")])
P = shore.port


def login(user, password):
    body, ctype = h.multipart({"user": user, "password": password})
    status, headers, data = h.request(P, "POST", "/api/login", body, {"Content-Type": ctype})
    cookie = headers.get("set-cookie", "")
    return status, cookie, (json.loads(data) if status == 200 else None)


def post(path, fields, cookie=None, csrf=None, files=(), content_type=None):
    body, ctype = h.multipart(fields, files)
    headers = {"Content-Type": content_type or ctype}
    if cookie:
        headers["Cookie"] = cookie.split(";")[0]
    if csrf:
        headers["X-CSRF-Token"] = csrf
    status, _, data = h.request(P, "POST", path, body, headers)
    return status, data


def get(path, cookie=None):
    return h.request(P, "GET", path, headers={"Cookie": cookie.split(";")[0]} if cookie else {})


try:
    # Unauthenticated.
    status, headers, _ = get("/")
    h.check(status == 303 and headers.get("location") == "/login", "unauthenticated page -> 303 /login (%d)" % status)
    for path in ("/api/fleet", "/api/gliders/g1", "/api/events", "/api/session", "/glider/g1"):
        status, _, _ = get(path)
        h.check(status in (401, 303), "unauthenticated GET %s refused (%d)" % (path, status))
    status, _ = post("/api/gliders/g1/command", {"command": "put u_x 1"})
    h.check(status == 401, "unauthenticated action refused (%d)" % status)
    h.check(get("/login")[0] == 200 and get("/static/console.css")[0] == 200, "the login page and its assets load")
    forged = "glider_session=" + "a" * 64
    h.check(get("/api/fleet", forged)[0] == 401, "a made-up session token is refused")

    # Log in.
    status, _, _ = login("pilot1", "wrong password")
    h.check(status == 401, "wrong password refused (%d)" % status)
    status, _, _ = login("nobody", "whatever password")
    h.check(status == 401, "unknown user refused (%d)" % status)
    status, vcookie, vsession = login("viewer1", "viewer password 1")
    h.check(status == 200 and "HttpOnly" in vcookie and "SameSite=Strict" in vcookie, "viewer logged in, cookie "
          "HttpOnly SameSite=Strict (%s)" % vcookie[:40])
    status, pcookie, psession = login("pilot1", "correct horse battery")
    h.check(status == 200 and psession["role"] == "pilot", "pilot logged in")
    login_time = time.time()
    h.check(get("/api/fleet", vcookie)[0] == 200, "the viewer may look")

    # Wrong role, CSRF.
    status, _ = post("/api/gliders/g1/command", {"command": "put u_x 1"}, vcookie, vsession["csrf"])
    h.check(status == 403, "viewer's action refused: wrong role (%d)" % status)
    status, _ = post("/api/gliders/g1/command", {"command": "put u_x 1"}, pcookie)
    h.check(status == 403, "pilot's action without a CSRF token refused (%d)" % status)
    status, _ = post("/api/gliders/g1/command", {"command": "put u_x 1"}, pcookie, vsession["csrf"])
    h.check(status == 403, "pilot's action with another session's CSRF token refused (%d)" % status)
    status, data = post("/api/gliders/g1/command", {"command": "put u_x 1"}, pcookie, psession["csrf"])
    h.check(status == 200, "pilot's action with its token done (%d %s)" % (status, data[:80]))
    journal = [json.loads(l) for l in open(os.path.join(root, "g1", "actions.journal"))]
    h.check(journal[-1]["user"] == "pilot1" and journal[-1]["command"] == "put u_x 1", "journaled with the user")
    h.check(open(os.path.join(root, "g1", "commands.queue")).read() == "put u_x 1\n", "the command is queued")

    # Path traversal: raw paths, encoded, in upload and cancel names.
    for path in ("/static/../../../../etc/passwd", "/static/..%2f..%2f..%2fetc%2fpasswd", "/glider/..%2f..%2fetc",
                 "/api/gliders/..%2fg1", "/api/gliders/g1/plots/..%2f..%2factions.journal",
                 "/api/gliders/g1/plots/%2e%2e%2fhealth.png", "/leaflet/../../../etc/passwd",
                 "/static/%2e%2e/%2e%2e/%2e%2e/etc/passwd"):
        status, _, data = get(path, pcookie)
        h.check(status in (400, 404) and b"root:" not in data, "traversal %s refused (%d)" % (path, status))
    os.makedirs(os.path.join(root, "g1", "health", "plots"), exist_ok=True)
    open(os.path.join(root, "g1", "health", "plots", "drag_change.png"), "wb").write(b"\x89PNG fixture")
    status, headers, data = get("/api/gliders/g1/plots/drag_change.png", pcookie)
    h.check(status == 200 and headers.get("content-type") == "image/png" and data == b"\x89PNG fixture",
            "a health plot is served (%d)" % status)
    h.check(get("/api/gliders/g1/plots/drag_change.png")[0] == 401, "not without a session")
    outside = os.path.join(root, "evil.ma")
    for name in ("../evil.ma", "..%2fevil.ma", "/tmp/evil.ma", "sub/evil.ma", ".hidden.ma", "evil.sh", "evil.ma\x00.txt"):
        status, data = post("/api/gliders/g1/queue", {}, pcookie, psession["csrf"],
                            files=[("file", name, b"behavior_name=goto_list\n")])
        h.check(status == 400 and not os.path.exists(outside), "upload named %r refused (%d)" % (name, status))
    status, _ = post("/api/gliders/g1/cancel", {"kind": "file", "name": "../commands.queue"}, pcookie, psession["csrf"])
    h.check(status == 400 and os.path.exists(os.path.join(root, "g1", "commands.queue")),
          "cancel of ../commands.queue refused (%d)" % status)
    status, _ = post("/api/gliders/..%2fg1/command", {"command": "x"}, pcookie, psession["csrf"])
    h.check(status == 404, "an action on a path-like glider refused (%d)" % status)

    # Size limits and bad input.
    status, _ = post("/api/gliders/g1/queue", {}, pcookie, psession["csrf"], files=[("file", "big.ma", b"x" * 65536)])
    h.check(status == 413, "a 64 KiB upload (limit 4096 + form) refused: 413 (%d)" % status)
    status, data = post("/api/gliders/g1/queue", {}, pcookie, psession["csrf"], files=[("file", "big.ma", b"#" * 5000)])
    h.check(status == 400 and b"allowed 1-4096" in data, "a 5000-byte .ma over --max-upload 4096 refused (%d %s)"
          % (status, data[:90]))
    status, _ = post("/api/gliders/g1/queue", {}, pcookie, psession["csrf"], files=[("file", "bin.ma", b"\x00\xff\x01")])
    h.check(status == 400, "a binary .ma refused (%d)" % status)
    for command in ("put u_x 1\x03", "x" * 129, "", "   ", "caf\xe9"):
        status, _ = post("/api/gliders/g1/command", {"command": command}, pcookie, psession["csrf"])
        h.check(status == 400, "command %r refused (%d)" % (command[:20], status))
    status, _ = post("/api/gliders/g1/cancel", {"kind": "command", "index": "-1", "command": "put u_x 1"}, pcookie,
                     psession["csrf"])
    h.check(status == 400, "cancel with a negative index refused (%d)" % status)
    h.check(not os.listdir(os.path.join(root, "g1", "to-glider")) if os.path.isdir(os.path.join(root, "g1", "to-glider"))
          else True, "nothing refused reached to-glider/")

    # Rehearsal gate (fixture rehearse program) and the explicit override.
    goto = b"behavior_name=goto_list\n<start:waypoints>\n724.5880 5420.0452\n<end:waypoints>\n"
    status, data = post("/api/gliders/g1/queue", {}, pcookie, psession["csrf"], files=[("file", "good.ma", goto)])
    h.check(status == 200 and json.loads(data)["rehearsal"]["verdict"] == "ok", "a rehearsed-ok .ma is queued (%d)" % status)
    status, data = post("/api/gliders/g1/queue", {}, pcookie, psession["csrf"], files=[("file", "will_abort.ma", goto)])
    h.check(status == 409 and not os.path.exists(os.path.join(root, "g1", "to-glider", "will_abort.ma")),
          "a .ma the rehearsal sees abort is not queued: 409 (%d)" % status)
    status, data = post("/api/gliders/g1/queue", {"force": "1"}, pcookie, psession["csrf"],
                        files=[("file", "will_abort.ma", goto)])
    h.check(status == 200 and os.path.exists(os.path.join(root, "g1", "to-glider", "will_abort.ma")),
          "with the explicit override it is queued (%d)" % status)
    journal = [json.loads(l) for l in open(os.path.join(root, "g1", "actions.journal"))]
    forced = [j for j in journal if j.get("file") == "will_abort.ma"]
    h.check(len(forced) == 2 and forced[0]["result"].startswith("not queued") and forced[1]["forced"] is True,
          "both attempts journaled, the override marked forced")
    status, data = post("/api/gliders/g1/cancel", {"kind": "file", "name": "will_abort.ma"}, pcookie, psession["csrf"])
    h.check(status == 200 and not os.path.exists(os.path.join(root, "g1", "to-glider", "will_abort.ma")), "cancelled")
    status, data = post("/api/gliders/g1/cancel", {"kind": "command", "index": "0", "command": "put u_x 1"}, pcookie,
                        psession["csrf"])
    h.check(status == 200 and open(os.path.join(root, "g1", "commands.queue")).read() == "", "command cancelled")

    # Lockout after 5 wrong passwords (each costs a scrypt).
    for _ in range(5):
        login("viewer1", "not the password")
    status, _, _ = login("viewer1", "viewer password 1")
    h.check(status == 429, "after 5 wrong passwords even the right one waits a minute (%d)" % status)

    # Logout, then expiry.
    status, _ = post("/api/logout", {"bye": "1"}, pcookie, psession["csrf"])
    h.check(status == 200 and get("/api/fleet", pcookie)[0] == 401, "after logout the session is gone (%d)" % status)
    time.sleep(max(0.0, login_time + 30.5 - time.time()))
    h.check(get("/api/fleet", vcookie)[0] == 401, "the viewer's session expired after --session-ttl 30 s")
finally:
    print(shore.stop()[-400:])

# Loopback without a login: still a Host check and the CSRF token.
shore = h.Shore(shore_bin, os.path.join(work, "open"), [])
try:
    status, _, _ = h.request(shore.port, "GET", "/api/fleet", headers={"Host": "evil.example:%d" % shore.port})
    h.check(status == 403, "loopback console: a foreign Host (DNS rebinding) refused (%d)" % status)
    os.makedirs(os.path.join(shore.root, "g2"), exist_ok=True)
    body, ctype = h.multipart({"command": "put u_x 1"})
    status, _, _ = h.request(shore.port, "POST", "/api/gliders/g2/command", body, {"Content-Type": ctype})
    h.check(status == 403, "loopback console: an action without the CSRF token refused (%d)" % status)
finally:
    shore.stop()
h.finish()
