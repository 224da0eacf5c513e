#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""What the console's tests share: a glider-shore with its console on an
ephemeral loopback port, HTTP helpers (raw requests, so a test can send
exactly the bytes an attacker would), and bounded waits."""
import http.client
import json
import os
import shutil
import subprocess
import sys
import time
import uuid


class Shore:
    def __init__(self, shore_bin, work, extra=(), http="127.0.0.1:0", env=None):
        self.root = os.path.join(work, "root")
        os.makedirs(self.root, exist_ok=True)
        self.port_file = os.path.join(work, "rudics.port")
        self.http_port_file = os.path.join(work, "http.port")
        for f in (self.port_file, self.http_port_file):
            if os.path.exists(f):
                os.remove(f)
        self.log_path = os.path.join(work, "shore.log")
        self.log = open(self.log_path, "w")
        args = [shore_bin, "serve", "--root", self.root, "--port", "0", "--port-file", self.port_file,
                "--http", http, "--http-port-file", self.http_port_file, *extra]
        self.proc = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT, env=env)
        wait_for(lambda: os.path.exists(self.http_port_file) and os.path.exists(self.port_file) or
                 self.proc.poll() is not None, 15, "the shore to listen")
        if self.proc.poll() is not None:
            raise RuntimeError("glider-shore exited %d: %s" % (self.proc.returncode, open(self.log_path).read()))
        self.port = int(open(self.http_port_file).read())
        self.rudics_port = int(open(self.port_file).read())
        self.host = "127.0.0.1"

    def url(self, path=""):
        return "http://%s:%d%s" % (self.host, self.port, path)

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.log.close()
        return open(self.log_path).read()


def wait_for(condition, seconds, what):
    deadline = time.time() + seconds
    while time.time() < deadline:
        if condition():
            return True
        time.sleep(0.05)
    raise TimeoutError("waited %.0f s for %s" % (seconds, what))


def request(port, method, path, body=None, headers=None, host="127.0.0.1"):
    """(status, headers dict lower-case, body bytes) of one request, sent as given."""
    c = http.client.HTTPConnection(host, port, timeout=20)
    c.putrequest(method, path, skip_host=True, skip_accept_encoding=True)
    h = {"Host": "127.0.0.1:%d" % port}
    h.update(headers or {})
    if body is not None:
        h["Content-Length"] = str(len(body))
    for k, v in h.items():
        c.putheader(k, v)
    c.endheaders()
    if body is not None:
        c.send(body)
    r = c.getresponse()
    data = r.read()
    c.close()
    return r.status, {k.lower(): v for k, v in r.getheaders()}, data


def multipart(fields, files=()):
    """(body, content type) of a multipart/form-data form: fields {name: value}, files [(field, filename, bytes)]."""
    boundary = uuid.uuid4().hex
    parts = []
    for k, v in fields.items():
        parts.append(("--%s\r\nContent-Disposition: form-data; name=\"%s\"\r\n\r\n%s\r\n" % (boundary, k, v)).encode())
    for field, filename, content in files:
        parts.append(("--%s\r\nContent-Disposition: form-data; name=\"%s\"; filename=\"%s\"\r\n"
                      "Content-Type: application/octet-stream\r\n\r\n" % (boundary, field, filename)).encode()
                     + content + b"\r\n")
    parts.append(("--%s--\r\n" % boundary).encode())
    return b"".join(parts), "multipart/form-data; boundary=" + boundary


def get_json(port, path, headers=None):
    status, _, data = request(port, "GET", path, headers=headers)
    return status, (json.loads(data) if data.startswith(b"{") or data.startswith(b"[") else None)


failures = []
_start = time.time()


def check(ok, what):
    """One named check: printed with the seconds since the test started; a failure is remembered."""
    print("%5.1f s %s %s" % (time.time() - _start, "ok  " if ok else "FAIL", what))
    if not ok:
        failures.append(what)
    return ok


def finish():
    print("PASS" if not failures else "FAILED: %d" % len(failures))
    sys.exit(1 if failures else 0)


def install_report(glider_dir, name):
    """Puts a real health or forecast report of tests/console/data (README.md there: glider-health's and
    glider-forecast's output in a console.browser run) into glider_dir, as those programs write it
    (CONTRACTS.md: a temporary in the same folder, then rename): NAME_health.json -> health/health.json,
    NAME_forecast.json -> forecast/forecast.json."""
    kind = name.rsplit("_", 1)[1].split(".")[0]
    folder = os.path.join(glider_dir, kind)
    os.makedirs(folder, exist_ok=True)
    tmp = os.path.join(folder, "." + kind + ".json.tmp")
    shutil.copy(os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", name), tmp)
    os.rename(tmp, os.path.join(folder, kind + ".json"))


def fresh_dir(path):
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path
