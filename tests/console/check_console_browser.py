#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The console in a real browser (headless Chromium driven by Selenium)
against a glider-shore fed by three SIL gliders over loopback RUDICS:
"healthy" (the box mission), "fouling" (the same; its hull fouls between two
runs: cd0 0.214 -> 0.300, drag +40 %) and "aborting" (a leak at 2500 s: the
firmware aborts, surfaces and calls). Their health and forecast are the
shore's own: after every call glider-shore runs health and the forecast
(tools/shore/station/after_surfacing.cpp) on the .sbd files the glider sent, with what
a pilot puts in each glider's folder: its vehicle file (GLIDER/vehicle.toml)
and a copy of the mission it flies (GLIDER/mission/). Steps:
 1. fleet page: three rows in attention order - aborting (abort), fouling
    (health's drag alert), healthy (health ok, a forecast);
 2. fouling's page: the map's fixes, dead-reckoned track, waypoints and the
    forecast ellipse; health's drag alert; the drag plot;
 3. aborting's page: the abort alert, the forecast box, acknowledged by a click;
 4. healthy's page: a goto .ma chosen in the file input and queued (the
    forecast's rehearsal shown); without a reload the page then shows the next
    calls, the file sent, and the journal shows it accepted by the SIL vehicle.
Screenshots of every page go to WORK_DIR/screenshots (and to --docs DIR).
Usage: check_console_browser.py GLIDER_SIL GLIDER_SHORE SOURCE_DIR WORK_DIR [--docs DIR].
Exit 0 pass, 1 fail, 77 skipped (no chromium, chromedriver or python3-selenium)."""
import glob
import json
import os
import re
import shutil
import subprocess
import sys
import time

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import console_harness as h  # noqa: E402

glider_sil, shore_bin, source, work = sys.argv[1:5]
docs = sys.argv[sys.argv.index("--docs") + 1] if "--docs" in sys.argv else None
CHROMIUM, DRIVER = shutil.which("chromium"), shutil.which("chromedriver")
try:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    from selenium.common.exceptions import StaleElementReferenceException
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import WebDriverWait
except ImportError:
    webdriver = None
LEAFLET = "/usr/share/javascript/leaflet/leaflet.js"
if webdriver is None or not CHROMIUM or not DRIVER or not os.path.exists(LEAFLET):
    print("SKIPPED: needs chromium, chromium-driver, python3-selenium and libjs-leaflet (./glider test installs them)")
    sys.exit(77)

h.fresh_dir(work)
shots = os.path.join(work, "screenshots")
os.makedirs(shots)


# Missions: box_current, the surface behaviour waiting for the pilot (as comms.e2e_sil_shore) so the
# shore's work fits in each call.
root = os.path.join(work, "root")
missions = {}
we01 = os.path.join(source, "boards/vehicles/slocum_we01.toml")
for g in ("healthy", "fouling", "aborting"):
    m = os.path.join(work, "mission_" + g)
    shutil.copytree(os.path.join(source, "boards/missions/box_current"), m)
    surfac = os.path.join(m, "mafiles/surfac10.ma")
    text = open(surfac).read().replace("b_arg: end_action(enum)          2   # resume",
                                       "b_arg: end_action(enum)          1\n    b_arg: keystroke_wait_time(s)  300")
    open(surfac, "w").write(text)
    missions[g] = os.path.join(m, "missions/box.mi")
    # What a pilot puts in the glider's shore folder before launch (docs/console.md, "feeding the console"):
    # a copy of the mission it flies, as the forecast reads it (GLIDER/mission/{missions,mafiles}/), and its
    # vehicle file, health's nominal vehicle (GLIDER/vehicle.toml; the fouling glider's too: nobody knows it
    # will foul).
    shutil.copytree(m, os.path.join(root, g, "mission"))
    shutil.copy(we01, os.path.join(root, g, "vehicle.toml"))
fouled = os.path.join(work, "fouled.toml")
text, n = re.subn(r"(?m)^cd0 = 0\.214", "cd0 = 0.300", open(we01).read())  # +40 % parasitic drag: a fouled hull
assert n == 1
open(fouled, "w").write(text)
# The .sbd's list: health's (tests/health/sbdlist.dat, 24 sensors, every 4 s at most). With the built-in
# list (depth every 10 s, pump 30 s) health's drag interval is wider than its 5 % rule: "cannot judge".
sbdlist = os.path.join(source, "tests/health/sbdlist.dat")
goto = os.path.join(work, "goto_l10.ma")
open(goto, "w").write("behavior_name=goto_list\n<start:b_arg>\n    b_arg: start_when(enum)          0\n"
                      "    b_arg: list_stop_when(enum)      7\n    b_arg: list_when_wpt_dist(m)   150\n"
                      "    b_arg: initial_wpt(enum)        -1\n    b_arg: num_waypoints(nodim)      1\n"
                      "    b_arg: num_legs_to_run(nodim)   -2\n<end:b_arg>\n<start:waypoints>\n722.0000 5417.9000\n"
                      "<end:waypoints>\n")

notify_log = os.path.join(work, "notify.log")
shore = h.Shore(shore_bin, work, ["--resume", "--linger", "20", "--identify-timeout", "20", "--prompt-timeout", "20",
                                  "--transfer-idle-timeout", "20", "--http-tick", "0.2",
                                  "--notify", "echo \"$GLIDER_ALERT_LEVEL $GLIDER_ALERT_ID\" >> " + notify_log])
sils = {}
# Simulated time flown by each run (s). A glider's clock (its Slocum files' m_present_time, its dialog's
# Curr Time) runs on from run to run and ends about now: run 1 of a glider starts its total flight ago.
FLIGHT = {("aborting", 1): 3600, ("fouling", 1): 4400, ("fouling", 2): 6800, ("healthy", 1): 6500,
          ("healthy", 2): 4500}
now = int(time.time())


def launch_utc(g, run):
    ago = sum(s for (name, _), s in FLIGHT.items() if name == g)
    t = now - ago + sum(FLIGHT[(g, r)] for r in range(1, run))
    return time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime(t))


def fly(g, vehicle, run=1, extra=()):
    """Run `run` of glider g. A later run flies on from the last fix, into the same Slocum folder (its
    files continue the glider's: the next mission number, the same name) and on the same clock."""
    log = open(os.path.join(work, "sil_%s_%d.log" % (g, run)), "w")
    if run > 1:
        fix = events(g)[-1]["gps"]
        extra = ("--launch-lat", str(fix["lat_deg"]), "--launch-lon", str(fix["lon_deg"]), *extra)
    sils[g] = subprocess.Popen([glider_sil, missions[g], "--vehicle", vehicle, "--max-sim-time-s",
                                str(FLIGHT[(g, run)]), "--launch-utc", launch_utc(g, run),
                                "--vehicle-name", g, "--shore", "127.0.0.1:%d" % shore.rudics_port,
                                "--slocum-dir", os.path.join(work, "slocum_" + g), "--sbdlist", sbdlist, *extra],
                               stdout=log, stderr=subprocess.STDOUT)


def events(g):
    return [json.load(open(p)) for p in sorted(glob.glob(os.path.join(root, g, "logs", "*.surfacing.json")))]


def after_surfacing_done(g):
    """The shore's health and forecast have run after every call of g: each call's journal ends with both
    notes (the shore runs them one glider at a time, after the call's event is written)."""
    calls = glob.glob(os.path.join(root, g, "logs", "*.surfacing.json"))
    journals = [open(p[:-len(".surfacing.json")] + ".journal").read() for p in calls]
    return len(calls) > 0 and all("* health: " in j and "* forecast: " in j for j in journals)


def health(g):
    return json.load(open(os.path.join(root, g, "health", "health.json")))


driver = None
try:
    fly("aborting", we01, extra=["--fault", "leak@2500"])
    fly("fouling", we01)
    fly("healthy", we01)
    for g in ("aborting", "fouling", "healthy"):
        sils[g].wait(timeout=40)
    fly("fouling", fouled, run=2)  # the same glider from its last fix, its hull fouled since
    sils["fouling"].wait(timeout=40)
    for g in ("aborting", "fouling", "healthy"):
        h.wait_for(lambda: after_surfacing_done(g), 40, "the shore's health and forecast after %s's calls" % g)
        report = health(g)
        print("        %s: %d calls; health %s, %d segments (%d judged), alerts %s" % (
            g, len(events(g)), report["state"], len(report["segments"]),
            sum(1 for s in report["segments"] if s["judged"]), [a["id"] for a in report["alerts"]]))
    h.check(sils["aborting"].returncode == 3 and any(e["prompt"].startswith("GliderDos A") for e in events("aborting")),
            "SIL 'aborting' aborted and called with the abort prompt")
    drag = [a for a in health("fouling")["alerts"] if a["effect"] == "drag_change"]
    h.check(health("fouling")["state"] == "alert" and len(drag) == 1 and drag[0]["size"] > 0.2,
            "health (the shore's, on fouling's .sbd) alerts on the drag's step: %s"
            % (drag[0]["message"] if drag else "-"))
    h.check(health("healthy")["state"] == "ok" and not health("healthy")["alerts"], "health: healthy is ok, no alert")
    forecasts = {g: json.load(open(os.path.join(root, g, "forecast", "forecast.json"))) for g in ("fouling", "healthy")}
    h.check(all(f.get("next_surfacing") for f in forecasts.values()), "the shore's forecast of fouling and healthy")

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for a in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage", "--window-size=1400,1000",
              "--user-data-dir=" + os.path.join(work, "chromium")):
        options.add_argument(a)
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    # The pages redraw on every change: an element found a moment ago may be replaced (stale): look again.
    wait = WebDriverWait(driver, 20, poll_frequency=0.1, ignored_exceptions=[StaleElementReferenceException])

    def retry(action):
        """An action on an element the page may redraw meanwhile: try again on a stale reference."""
        for _ in range(50):
            try:
                return action()
            except StaleElementReferenceException:
                time.sleep(0.05)
        return action()

    def text(css):
        return retry(lambda: driver.find_element(By.CSS_SELECTOR, css).text)

    def texts(css):
        """Every match's text, found and read again together if the page redrew one meanwhile."""
        return retry(lambda: [e.text for e in driver.find_elements(By.CSS_SELECTOR, css)])

    def click(css):
        retry(lambda: driver.find_element(By.CSS_SELECTOR, css).click())

    def shot(name, height=None):
        if height:
            driver.set_window_size(1400, height)
        path = os.path.join(shots, name)
        driver.execute_script("window.scrollTo(0, 0)")  # a click may have scrolled the page: shoot it from the top
        time.sleep(0.2)
        driver.save_screenshot(path)
        print("        screenshot", path)

    # 1. Fleet.
    driver.get(shore.url("/"))
    order = []

    def fleet_ready(d):
        nonlocal_order = [r.get_attribute("id")[4:] for r in d.find_elements(By.CSS_SELECTOR, "#fleet tbody tr")]
        order[:] = nonlocal_order
        return nonlocal_order == ["aborting", "fouling", "healthy"]
    try:
        wait.until(fleet_ready)
    except Exception:
        pass
    h.check(order == ["aborting", "fouling", "healthy"], "fleet ordered by attention: %s" % order)
    row = {g: text("#row-" + g) for g in order}
    h.check("aborted" in row.get("aborting", "") and "no forecast yet" in row.get("aborting", ""),
          "aborting's row: aborted, no forecast yet (the shore's forecast, made as if it dived on, set aside)")
    h.check("health alert" in row.get("fouling", ""), "fouling's row: health alert")
    h.check(re.search(r"\d+ s ago|\d+ min ago", row.get("healthy", "")) is not None, "time since the last call shown")
    shot("fleet.png", 700)

    # 2. Fouling: map, forecast ellipse, alert, plot; text from files shown as text, never as HTML.
    evil = '<img src=x onerror="window.pwned=1">'
    subprocess.run([shore_bin, "queue", "--root", root, "fouling", "--command", "put " + evil], check=True,
                   capture_output=True)
    open(os.path.join(root, "fouling", "mission", "mafiles", evil.replace("/", "") + ".ma"), "w").write(
        open(os.path.join(root, "fouling", "mission", "mafiles", "goto_l10.ma")).read())
    driver.get(shore.url("/glider/fouling"))
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, "path.forecast-ellipse"))
    counts = {c: len(driver.find_elements(By.CSS_SELECTOR, "path." + c))
              for c in ("fix", "dr-track", "waypoints", "waypoint", "forecast-ellipse", "forecast-point")}
    print("        map layers:", counts)
    h.check(counts["fix"] == len(events("fouling")) and counts["dr-track"] == 1 and counts["forecast-ellipse"] == 1 and
          counts["waypoints"] >= 1, "map: one marker a fix, the DR track, waypoints, the forecast ellipse")
    alerts = texts("#alerts .alert[data-kind=health]")
    h.check(len(alerts) == 1 and "drag_change changed by" in alerts[0], "health's drag alert is on the page")
    # The drag plot: health's own (gnuplot, thresholds drawn by health), else the page's SVG with its thresholds.
    png = driver.execute_script("const i = document.querySelector('img.effect-png[alt=drag_change]');"
                                "return i ? i.complete && i.naturalWidth : null")
    h.check(png or len(driver.find_elements(By.CSS_SELECTOR, "svg.effect-plot line.threshold")) >= 2,
            "the drag plot (%s)" % ("health's PNG, %d px wide" % png if png else "SVG with its threshold lines"))
    h.check(len(driver.find_elements(By.CSS_SELECTOR, "#surfacings tr.surfacing")) == len(events("fouling")),
          "one table row a surfacing")
    dr = texts("#surfacings tr.surfacing td:nth-child(4)")
    h.check(any(re.fullmatch(r"\d+ m", t) for t in dr), "DR error shown at the surfacings with received files: %s" % dr)
    wait.until(lambda d: d.execute_script("return GliderMap.layer.getLayers().filter(l => l.getTooltip && "
                                          "l.getTooltip() && String(l.getTooltip().getContent().textContent || "
                                          "l.getTooltip().getContent()).includes('onerror')).length") > 0)
    driver.execute_script("GliderMap.layer.eachLayer(l => { if (l.getTooltip && l.getTooltip()) l.openTooltip(); })")
    h.check(driver.execute_script("return window.pwned") is None and not driver.find_elements(By.CSS_SELECTOR, "img[src=x]")
            and evil in text("#queued"), "a command and a file name holding HTML are shown as text (no script ran)")
    click("#cancel-command-0")
    try:
        wait.until(lambda d: evil not in text("#queued"))
    except Exception:
        h.check(False, "the cancelled command is gone from the page within 20 s; the page said %r; actions.journal: %r" %
                (text("#queue-result"),
                open(os.path.join(root, "fouling", "actions.journal")).read()[-600:]
                 if os.path.exists(os.path.join(root, "fouling", "actions.journal")) else None))
        raise
    os.remove(os.path.join(root, "fouling", "mission", "mafiles", evil.replace("/", "") + ".ma"))
    shot("glider_fouling.png", 3000)

    # 3. Aborting: abort alert, no forecast, acknowledge.
    driver.set_window_size(1400, 1000)
    driver.get(shore.url("/glider/aborting"))
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, "#alerts .alert[data-kind=abort] button.ack"))
    h.check("MS_ABORT_LEAK" in text("#alerts .alert[data-kind=abort]"),
          "the abort alert names MS_ABORT_LEAK")
    # The shore's forecast flies the dive cycle on from the abort call's fix; the glider waits at the surface
    # for the pilot instead: the page sets it aside and says why.
    h.check(text("#no-forecast").startswith("no forecast: set aside"), "'no forecast' shown: " + text("#no-forecast"))
    click("#alerts .alert[data-kind=abort] button.ack")
    wait.until(lambda d: "acked by" in text("#alerts .alert[data-kind=abort]"))
    h.check(True, "acknowledged from the page (the alert shows who)")
    shot("glider_aborting.png", 2600)

    # 4. Healthy: queue a goto .ma through the page; it reaches the vehicle at its next call: a second SIL
    # run of the glider from its last fix (a SIL run cannot be paused while a browser works).
    driver.set_window_size(1400, 1000)
    driver.get(shore.url("/glider/healthy"))
    wait.until(lambda d: d.find_elements(By.CSS_SELECTOR, "#surfacings tr.surfacing"))
    before = int(driver.find_element(By.TAG_NAME, "body").get_attribute("data-surfacings"))
    driver.find_element(By.ID, "queue-file").send_keys(goto)
    click("#queue-button")
    wait.until(lambda d: text("#queue-result"))
    if retry(lambda: driver.find_element(By.ID, "force-label").is_displayed()):  # a real rehearsal said no: override
        print("        rehearsal:", text("#queue-result"), "- overriding, explicitly")
        driver.find_element(By.ID, "queue-file").send_keys(goto)
        click("#force")
        click("#queue-button")
        wait.until(lambda d: "queued" == text("#action-result"))
    verdict = text("#rehearsal-verdict")
    h.check(text("#action-result") == "queued" and verdict.startswith("rehearsal: "),
          "queued from the page, rehearsal shown: '%s'" % verdict)
    shot("glider_healthy_queued.png", 3000)
    driver.set_window_size(1400, 1000)
    fly("healthy", we01, run=2)
    sent_seen = False
    try:
        WebDriverWait(driver, 30, poll_frequency=0.2, ignored_exceptions=[StaleElementReferenceException]).until(
            lambda d: any("goto_l10.ma" in e.text for e in d.find_elements(By.CSS_SELECTOR, "li.sent-file")) and
            int(d.find_element(By.TAG_NAME, "body").get_attribute("data-surfacings")) > before)
        sent_seen = True
    except Exception:
        pass
    after = int(driver.find_element(By.TAG_NAME, "body").get_attribute("data-surfacings"))
    h.check(sent_seen and after > before, "without a reload the page shows goto_l10.ma sent and %d new calls"
          % (after - before))
    h.wait_for(lambda: any("goto_l10.ma accepted" in open(j).read()
                           for j in glob.glob(os.path.join(root, "healthy", "logs", "*.journal"))), 30,
               "the vehicle to accept goto_l10.ma")
    h.check(True, "the SIL vehicle accepted goto_l10.ma at its next call (journal)")
    rows = retry(lambda: [e.text for e in driver.find_elements(By.CSS_SELECTOR, "#actions tr.action")])
    h.check(any("queue_file goto_l10.ma" in r and "local" in r for r in rows), "the actions journal names the user")
    h.check("queue_file" in open(os.path.join(root, "healthy", "actions.journal")).read(), "actions.journal written")
    wait.until(lambda d: "goto_l10.ma accepted" in text("#transcript") or
               any("goto_l10.ma accepted" in e.text for e in d.find_elements(By.CSS_SELECTOR, "#surfacings pre")))
    h.check(True, "the acceptance is in the page's dialog excerpt or transcript")
    shot("glider_healthy_sent.png", 3000)
    notes = open(notify_log).read() if os.path.exists(notify_log) else ""
    h.check("notify abort@" in notes, "the abort was notified through --notify")
except Exception as error:  # a timeout or a missing element: a failure with its reason, not a crash
    import traceback
    traceback.print_exc()
    h.check(False, "%s: %s" % (type(error).__name__, str(error).splitlines()[0] if str(error) else ""))
    if driver is not None:  # what the page showed then
        print("page at the failure:", driver.current_url)
        print(driver.find_element(By.TAG_NAME, "body").text[:2000])
        driver.save_screenshot(os.path.join(shots, "failure.png"))
finally:
    if driver is not None:
        driver.quit()
    for p in sils.values():
        if p.poll() is None:
            p.terminate()
            p.wait(10)
    print(shore.stop()[-500:])
if docs:
    os.makedirs(docs, exist_ok=True)
    for png in glob.glob(os.path.join(shots, "*.png")):
        shutil.copy(png, docs)
print("screenshots in %s" % shots)
h.finish()
