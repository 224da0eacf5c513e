#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The console's alerts to people (docs/console.md, "Alerts"), on a shore root
of fake calls (fake_events.py) and real health and forecast reports
(tests/console/data): an abort, a missed call (the forecast's p90 passed by
the margin), too long at the surface (a call in progress past the limit) and a
health alert each raise one alert, notified through the --notify command
(GLIDER_ALERT_* in its environment), repeated and escalated while nobody
acknowledges; an acknowledgement (pilot, CSRF token) stops the repeats, is
journaled with the user, and survives a restart. The fleet is ordered by
them. Usage: check_console_alerts.py GLIDER_SHORE WORK_DIR. Exit 0 = pass."""
import calendar
import json
import os
import shutil
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import console_harness as h  # noqa: E402
import fake_events  # noqa: E402

shore_bin, work = sys.argv[1:3]
h.fresh_dir(work)


root = os.path.join(work, "root")
# Calls of one glider an hour apart (more than the 2400 s that make one stay at the surface), but g_surface's.
fake_events.write_call(root, "g_abort", 3630, 1)
abort_id = fake_events.write_call(root, "g_abort", 20, 2, prompt="GliderDos A 6 >", aborts=1, cause="MS_ABORT_LEAK")
# g_missed: two calls an hour apart, the last when its forecast was made (27 Nov 2026, 12:07 UTC: a real one,
# tests/console/data), which expected the next call by 12:39 UTC that day, long past.
h.install_report(os.path.join(root, "g_missed"), "healthy_forecast.json")
made = json.load(open(os.path.join(root, "g_missed", "forecast", "forecast.json")))["made_utc"]
made_ago = time.time() - calendar.timegm(time.strptime(made, "%Y-%m-%dT%H:%M:%SZ"))
for n in (1, 2):
    fake_events.write_call(root, "g_missed", made_ago + 3600 * (2 - n), n)
fake_events.write_call(root, "g_surface", 60, 1)
fake_events.write_call(root, "g_surface", 12, 2, event=False)  # the call in progress, 12 s long
fake_events.write_call(root, "g_health", 30, 1)
h.install_report(os.path.join(root, "g_health"), "fouling_health.json")  # health's drag alert
fake_events.write_call(root, "g_fine", 30, 1)
h.install_report(os.path.join(root, "g_fine"), "healthy_health.json")  # ok; one call, no forecast: none expected

notify_log = os.path.join(work, "notify.log")
notify = ("printf '%s|%s|%s|%s\\n' \"$GLIDER_ALERT_LEVEL\" \"$GLIDER_ALERT_ID\" \"$GLIDER_ALERT_KIND\" "
          "\"$GLIDER_ALERT_MESSAGE\" >> " + notify_log)
options = ["--notify", notify, "--alert-repeat", "1", "--escalate-after", "2.5", "--surface-limit", "5",
           "--missed-call-margin", "1", "--http-tick", "0.1"]


def notes():
    if not os.path.exists(notify_log):
        return []
    return [line.rstrip("\n").split("|") for line in open(notify_log)]


shore = h.Shore(shore_bin, work, options)
try:
    h.wait_for(lambda: len({n[1] for n in notes()}) >= 4, 10, "a notification of each of the four alerts")
    first = notes()
    kinds = {n[2] for n in first}
    h.check(kinds == {"abort", "missed_call", "surface_too_long", "health"},
          "one alert each: abort, missed call, too long at the surface, health (%s)" % sorted(kinds))
    h.check(not any(n[1].startswith("g_fine") or "g_fine" in n[3] for n in first), "the healthy glider raises nothing")
    h.check(any(n[2] == "abort" and "MS_ABORT_LEAK" in n[3] for n in first), "the abort's message names its cause")
    status, fleet = h.get_json(shore.port, "/api/fleet")
    order = [g["name"] for g in fleet["gliders"]]
    print("fleet order:", order, [g["attention"]["why"] for g in fleet["gliders"]])
    h.check(order == ["g_abort", "g_missed", "g_surface", "g_health", "g_fine"],
          "fleet ordered abort, missed call, surface, health, ok")
    h.wait_for(lambda: sum(n[0] == "escalate" for n in notes()) >= 4, 8, "four escalations")
    print("\n".join("|".join(n) for n in notes()))
    h.check(all(any(n[0] == "escalate" and n[1].startswith(k) for n in notes())
              for k in ("abort@", "missed_call@", "surface@", "health:")), "every unacknowledged alert escalated")
    # Acknowledge the abort on the page's API: CSRF token from the session.
    _, session = h.get_json(shore.port, "/api/session")
    alert_id = "abort@" + abort_id
    body, ctype = h.multipart({"id": alert_id, "glider": "g_abort"})
    status, _, data = h.request(shore.port, "POST", "/api/alerts/ack", body,
                                {"Content-Type": ctype, "X-CSRF-Token": session["csrf"]})
    h.check(status == 200, "acknowledged (%d %s)" % (status, data[:100]))
    time.sleep(0.3)
    count = sum(1 for n in notes() if n[1] == alert_id)
    others = sum(1 for n in notes() if n[1] != alert_id)
    time.sleep(2.5)
    h.check(sum(1 for n in notes() if n[1] == alert_id) == count, "no repeat of the acknowledged alert in 2.5 s")
    h.check(sum(1 for n in notes() if n[1] != alert_id) >= others + 3, "the others keep repeating (every 1 s)")
    saved = json.load(open(os.path.join(root, "g_abort", "alerts.json")))
    rec = [a for a in saved["alerts"] if a["id"] == alert_id][0]
    h.check(rec["acked_by"].startswith("local") and rec["acked_utc"], "alerts.json: acknowledged by the local pilot")
    journal = [json.loads(l) for l in open(os.path.join(root, "g_abort", "actions.journal"))]
    h.check(any(j["action"] == "ack_alert" and j["alert"] == alert_id for j in journal), "the ack is journaled")
    status, _, _ = h.request(shore.port, "POST", "/api/alerts/ack", body, {"Content-Type": ctype})
    h.check(status == 403, "an ack without the CSRF token is refused (%d)" % status)
finally:
    print(shore.stop()[-600:])

# Restart: the acknowledgement holds.
count = sum(1 for n in notes() if n[1] == alert_id)
shore = h.Shore(shore_bin, work, options)
try:
    time.sleep(1.5)
    h.check(sum(1 for n in notes() if n[1] == alert_id) == count, "after a restart the acknowledged alert stays quiet")
    _, d = h.get_json(shore.port, "/api/gliders/g_abort")
    h.check(any(a["id"] == alert_id and a["acked_by"] for a in d["alerts"]), "the page still shows who acknowledged it")
finally:
    shore.stop()
h.finish()
