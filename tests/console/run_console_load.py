#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The console under load (`./glider benchmark console`, and CTest console.load):
a glider-shore with its console on loopback over a fixture fleet (12 gliders,
40 calls each, one with a 3000-point DR track from a received-file CSV, health
and forecast reports), a new call written every 0.5 s (so every event stream
gets changes and the snapshot is rebuilt under load), and console_load's page
clients and event streams for a bounded time. Prints the figures; with
--max-p99-ms the run fails (exit 1) if the page latency p99 is above it, any
request failed, or a stream did not open.
Usage: run_console_load.py BUILD_DIR SOURCE_DIR [--clients 200] [--streams 50] [--seconds 10] [--max-p99-ms MS]"""
import argparse
import json
import os
import subprocess
import sys
import threading
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import console_harness as h  # noqa: E402
import fake_events  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("build")
ap.add_argument("source")
ap.add_argument("--clients", type=int, default=200)
ap.add_argument("--streams", type=int, default=50)
ap.add_argument("--seconds", type=float, default=10.0)
ap.add_argument("--max-p99-ms", type=float, default=None)
a = ap.parse_args()
work = h.fresh_dir(os.path.join(a.build, "tests", "console", "output", "load"))
root = os.path.join(work, "root")
gliders = ["g%02d" % i for i in range(12)]
for i, g in enumerate(gliders):
    for n in range(40):
        fake_events.write_call(root, g, 3600 * 4 * (40 - n), n + 1, lat=54.3 + 0.01 * n, lon=7.4 + 0.01 * i)
    h.install_report(os.path.join(root, g), "fouling_health.json" if i % 4 == 0 else "healthy_health.json")
    h.install_report(os.path.join(root, g), "healthy_forecast.json")
csv = os.path.join(root, "g00", "from-glider", "g00-2026-330-0-0.sbd.csv")
os.makedirs(os.path.dirname(csv))
with open(csv, "w") as f:  # 3000 DR rows then a fix: a long segment's track
    f.write("# fixture\nm_present_time,m_gps_lat,m_gps_lon,m_lat,m_lon\n")
    for k in range(3000):
        f.write("%d,,,%.4f,%.4f\n" % (k, 5418.0 + k * 0.001, 724.0 + k * 0.0005))
    f.write("3000,5421.0100,725.5000,,\n")

shore = h.Shore(os.path.join(a.build, "tools", "shore", "station", "glider-shore"), work,
                ["--http-threads", str(max(64, a.clients + a.streams + 16)), "--max-streams", str(a.streams + 10)])
stop = threading.Event()


def new_calls():  # a call every 0.5 s somewhere in the fleet
    n = 100
    while not stop.wait(0.5):
        fake_events.write_call(root, gliders[n % len(gliders)], 0, n)
        n += 1


changer = threading.Thread(target=new_calls)
changer.start()
try:
    status, page = h.get_json(shore.port, "/api/gliders/g00")
    size = len(json.dumps(page))
    cmd = [os.path.join(a.build, "tests", "console", "console_load"), "--port", str(shore.port), "--clients",
           str(a.clients), "--streams", str(a.streams), "--seconds", str(a.seconds)]
    for p in ("/", "/api/fleet", "/glider/g00", "/api/gliders/g00", "/static/console.js"):
        cmd += ["--path", p]
    t0 = time.time()
    out = subprocess.run(cmd, capture_output=True, text=True, timeout=a.seconds + 60)
    result = json.loads(out.stdout.strip().splitlines()[-1])
finally:
    stop.set()
    changer.join()
    log = shore.stop()
load = os.getloadavg()
print("console load: %d page clients (keep-alive, pages + their JSON in turn) and %d event streams for %.1f s"
      % (result["clients"], result["streams"], result["seconds"]))
print("  fleet: %d gliders x 40 calls; g00's page JSON %d bytes (3000-point DR track); a new call every 0.5 s"
      % (len(gliders), size))
print("  requests %d (%.0f/s), errors %d" % (result["requests"], result["requests_per_s"], result["errors"]))
print("  page latency ms: p50 %.2f  p90 %.2f  p99 %.2f  max %.2f" % (result["p50_ms"], result["p90_ms"],
                                                                       result["p99_ms"], result["max_ms"]))
print("  event streams open %d of %d, errors %d, change events received %d" % (
    result["streams_open"], result["streams"], result["stream_errors"], result["stream_events"]))
print("  load average after: %.1f %.1f %.1f on %d cores" % (load[0], load[1], load[2], os.cpu_count()))
print(json.dumps(result))
if a.max_p99_ms is not None:
    ok = (result["p99_ms"] <= a.max_p99_ms and result["errors"] == 0 and result["streams_open"] == result["streams"]
          and result["stream_errors"] == 0 and result["stream_events"] >= result["streams"])
    print(("PASS" if ok else "FAIL") + " p99 %.2f ms (limit %.0f), %d errors, %d/%d streams, %d events" % (
        result["p99_ms"], a.max_p99_ms, result["errors"], result["streams_open"], result["streams"],
        result["stream_events"]))
    sys.exit(0 if ok else 1)
