#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Loopback tests of glider-shore against the scripted fake glider (fake_glider.py).

usage: check_shore.py GLIDER_SHORE SCENARIO WORKDIR
Scenarios: call, carrier_drop, two_gliders, busy, garbage, unidentified, dialog.
Skips (exit 77) when Debian's lrzsz (sz/rz) is not installed.
"""
import atexit
import glob
import hashlib
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REAL = os.path.join(HERE, "..", "data", "real", "dbd", "comet-2019")
FAKE = [sys.executable, os.path.join(HERE, "fake_glider.py")]
JOURNAL_LINE = re.compile(r"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z [<>*] ")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)
    print("ok: " + message)


def sha(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


STARTED = []


def kill_leftovers():
    """A failed check must not leave a shore running after the test."""
    for proc in STARTED:
        if proc.poll() is None:
            proc.kill()
            proc.wait()


class Shore:
    """glider-shore serve on a free loopback port, stopped by SIGTERM."""

    def __init__(self, exe, root, *extra):
        self.port_file = os.path.join(root + ".port")
        if os.path.exists(self.port_file):
            os.remove(self.port_file)
        self.err = open(root + ".stderr", "w")
        self.proc = subprocess.Popen([exe, "--root", root, "serve", "--port", "0", "--port-file", self.port_file,
                                      "--fetch", "*.dbd *.cac", "--linger", "20", "--prompt-timeout", "10",
                                      "--transfer-idle-timeout", "5"] + list(extra),
                                     stderr=self.err)
        STARTED.append(self.proc)
        for _ in range(400):  # 20 s: a loaded machine starts programs slowly
            if os.path.exists(self.port_file):
                self.port = int(open(self.port_file).read())
                return
            time.sleep(0.05)
        fail("glider-shore did not start listening")

    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        try:
            rc = self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            fail("glider-shore did not stop on SIGTERM")
        check(rc == 0, "glider-shore stops cleanly on SIGTERM (exit %d)" % rc)


def make_card(work, name, files):
    """The fake glider's data folder: real Slocum files and their sensor-list caches."""
    card = os.path.join(work, name + "-card")
    os.makedirs(card, exist_ok=True)
    for f in files:
        shutil.copy(os.path.join(REAL, f), card)
    for cac in glob.glob(os.path.join(REAL, "cac", "*.cac")):
        shutil.copy(cac, card)
    return card


def run_glider(port, name, card, work, *extra, timeout=45):
    record = os.path.join(work, name + ".record.jsonl")
    rc = subprocess.call(FAKE + ["--port", str(port), "--name", name, "--files", card,
                                 "--inbox", os.path.join(work, name + "-inbox"), "--record", record] + list(extra),
                         timeout=timeout)
    lines = [json.loads(l) for l in open(record)] if os.path.exists(record) else []
    return rc, lines


def events(root, glider):
    paths = sorted(glob.glob(os.path.join(root, glider, "logs", "*.surfacing.json")))
    return [json.load(open(p)) for p in paths]


def wait_for_events(root, glider, count, seconds=30):
    for _ in range(int(seconds * 10)):
        if len(events(root, glider)) >= count:
            return events(root, glider)
        time.sleep(0.1)
    fail("%s: %d surfacing event(s) expected in %d s" % (glider, count, seconds))


def check_journal(path):
    lines = open(path, encoding="ascii").read().splitlines()
    check(all(JOURNAL_LINE.match(l) for l in lines), "journal %s: every line is 'TIME DIR TEXT'" %
          os.path.basename(path))
    return lines


def published_files(root, glider):
    d = os.path.join(root, glider, "from-glider")
    return sorted(f for f in os.listdir(d) if os.path.isfile(os.path.join(d, f)))


def scenario_call(exe, work):
    root = os.path.join(work, "root")
    card = make_card(work, "unit_345", ["comet-2019-222-02-154.dbd", "comet-2019-222-02-155.dbd"])
    ma = os.path.join(work, "goto_l10.ma")
    with open(ma, "w") as f:
        f.write("behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 1\n<end:b_arg>\n")
    subprocess.check_call([exe, "--root", root, "queue", "unit_345", ma, "--command", "put u_x 3"])
    subprocess.check_call([exe, "--root", root, "queue", "unit_345", "--command", "get m_battery"])
    status = json.loads(subprocess.check_output([exe, "--root", root, "status", "--json"]))
    check(status[0]["queued_commands"] == ["put u_x 3", "get m_battery"] and status[0]["queued_files"] ==
          ["goto_l10.ma"], "status lists the queue before the call")
    shore = Shore(exe, root, "--resume")
    rc, said = run_glider(shore.port, "unit_345", card, work)
    ev = wait_for_events(root, "unit_345", 1)[0]
    shore.stop()
    commands = [l["command"] for l in said if "command" in l]
    check(commands == ["whoru", "put u_x 3", "get m_battery", "zr", "send *.dbd *.cac", "^R"],
          "the shore typed whoru, the queued commands in order, zr, send, ^R: %s" % commands)
    inbox = os.path.join(work, "unit_345-inbox", "goto_l10.ma")
    check(os.path.exists(inbox) and sha(inbox) == sha(ma), "the glider received the queued .ma intact by Zmodem")
    folders = os.path.join(root, "unit_345")
    check(not os.path.exists(os.path.join(folders, "to-glider", "goto_l10.ma")) and
          len(glob.glob(os.path.join(folders, "to-glider", "sent", "*_goto_l10.ma"))) == 1,
          "the sent file moved to to-glider/sent/")
    check(open(os.path.join(folders, "commands.queue")).read() == "", "the command queue is empty after the call")
    for name in ["comet-2019-222-02-154.dbd", "comet-2019-222-02-155.dbd"]:
        got = os.path.join(folders, "from-glider", name)
        check(os.path.exists(got) and sha(got) == sha(os.path.join(REAL, name)),
              "%s received byte-identical to the glider's file" % name)
        csv = got + ".csv"
        check(os.path.exists(csv), "%s converted to CSV beside it" % name)
    header = [l for l in open(os.path.join(folders, "from-glider", "comet-2019-222-02-154.dbd.csv"))
              if not l.startswith("#")][0]
    rows = sum(1 for l in open(os.path.join(folders, "from-glider", "comet-2019-222-02-154.dbd.csv"))
               if not l.startswith("#")) - 1
    check("m_depth" in header and rows > 1000, "the CSV has m_depth and %d rows" % rows)
    check(not any(f.startswith(".") for f in published_files(root, "unit_345")), "no temporary name in from-glider/")
    check(os.listdir(os.path.join(folders, ".incoming")) == [], "nothing left in .incoming/")
    # The event
    check(ev["schema"] == "glider-shore-surfacing/1" and ev["glider"] == "unit_345", "event schema and glider")
    check(ev["glider_time"]["utc"] == "2026-11-27T05:40:12Z" and ev["glider_time"]["mission_time_s"] == 43211,
          "event glider time from Curr Time: (%s)" % ev["glider_time"])
    gps = ev["gps"]
    check(abs(gps["lat_deg"] - (43 + 19.4 / 60)) < 1e-9 and abs(gps["lon_deg"] + (7 + 26.9 / 60)) < 1e-9 and
          gps["age_s"] == 12.034, "event GPS fix in decimal degrees, west negative (%s)" % gps)
    check([g["kind"] for g in ev["gps_rejected"]] == ["gps_toofar", "gps_invalid"] and
          ev["gps_rejected"][0]["age_s"] is None, "TooFar and Invalid lines kept apart, 1e+308 s as null")
    check(abs(ev["dr"]["lat_deg"] - (43 + 19.412 / 60)) < 1e-9, "event DR location")
    check(ev["reasons"] == ["Hit a waypoint [behavior surface_2 start_when = 7.0]",
                            "no comms for a while [behavior surface_3 start_when = 12.0]"],
          "event surfacing reasons (Because:)")
    check(ev["aborts"]["total_since_reset"] == 1 and ev["aborts"]["last_cause"] == "MS_ABORT_OVERTIME" and
          ev["aborts"]["last_time"] == "2026-11-26T22:10:05", "event abort history")
    sensors = {s["name"]: s for s in ev["sensors"]}
    check(sensors["m_battery"]["value"] == 14.8812 and sensors["m_battery"]["unit"] == "volts" and
          sensors["m_battery"]["age_s"] == 10.41 and len(sensors) == 7, "event sensors (name, unit, value, age)")
    check(ev["devices"]["warnings"] == [1, 1, 0] and ev["devices"]["oddities"] == [3, 0, 0], "event devices line")
    check(ev["commands_sent"] == ["put u_x 3", "get m_battery"], "event commands sent")
    check([f["name"] for f in ev["files_sent"]] == ["goto_l10.ma"] and ev["files_sent"][0]["delivered"],
          "event files sent")
    received = {f["name"]: f for f in ev["files_received"]}
    check(len(received) == 6 and received["comet-2019-222-02-154.dbd"]["status"] == "new" and
          received["comet-2019-222-02-154.dbd"]["csv"] == "comet-2019-222-02-154.dbd.csv",
          "event files received (2 .dbd + 4 .cac) with their CSV")
    check(ev["prompt"] == "GliderDos N -1 >" and ev["end_reason"] == "hangup", "event prompt and end (hangup)")
    lines = check_journal(os.path.join(folders, "logs", ev["journal"]))
    check(any(" > put u_x 3" in l for l in lines) and any(" < GPS Location:" in l for l in lines) and
          any(" * received comet-2019-222-02-155.dbd" in l for l in lines), "journal has both directions and notes")
    # A second call: the same files again are duplicates, not re-published.
    # The restarted shore counts its calls from 1 again: journals of earlier
    # calls named for the coming seconds (as a call in the same second leaves
    # them) must be neither appended to nor overwritten.
    now = time.time()
    earlier = {}
    for k in range(-1, 30):
        stamp = time.strftime("%Y%m%dT%H%M%S", time.gmtime(now + k))
        path = os.path.join(folders, "logs", stamp + "_0001.journal")
        if not os.path.exists(path):
            with open(path, "w") as f:
                f.write("earlier call %s\n" % stamp)
            earlier[path] = "earlier call %s\n" % stamp
    shore = Shore(exe, root)
    rc2, _ = run_glider(shore.port, "unit_345", card, work)
    ev2 = wait_for_events(root, "unit_345", 2)[1]
    shore.stop()
    check(rc2 == 0, "second call: the glider's side ended cleanly (exit %d)" % rc2)
    check(all(open(p).read() == text for p, text in earlier.items()) and ev2["journal"].endswith("_0002.journal"),
          "a restarted shore claims a free journal name (%s), earlier calls' journals untouched" % ev2["journal"])
    for path in earlier:
        os.remove(path)
    check(all(f["status"] == "duplicate" for f in ev2["files_received"]) and ev2["commands_sent"] == [],
          "second call: same files are duplicates, nothing queued is sent twice")
    text = subprocess.check_output([exe, "--root", root, "status"]).decode()
    check("unit_345" in text and "last surfacing" in text and "43.32333" in text, "status shows the last surfacing")


def scenario_carrier_drop(exe, work):
    root = os.path.join(work, "root")
    card = make_card(work, "unit_346", ["comet-2019-222-02-154.dbd"])
    shore = Shore(exe, root)
    # The .cac files (4 x <= 92 kB) go first, then the 1.8 MB .dbd is cut after ~1 MB.
    rc, said = run_glider(shore.port, "unit_346", card, work, "--drop-after", "1000000")
    ev = wait_for_events(root, "unit_346", 1)[0]
    check(any("dropped_after" in l for l in said), "the fake glider hung up mid-transfer")
    published = published_files(root, "unit_346")
    check("comet-2019-222-02-154.dbd" not in published and not any(f.endswith(".csv") for f in published),
          "the cut .dbd is not published (from-glider: %s)" % published)
    check(not any(f.startswith(".") or f.endswith(".tmp") for f in published), "no temporary file in from-glider/")
    check(ev["end_reason"] == "carrier lost during transfer" and
          ev["partial_files"] == ["comet-2019-222-02-154.dbd"], "event: carrier lost, partial kept for resume")
    partial = os.path.join(root, "unit_346", ".incoming", "comet-2019-222-02-154.dbd")
    size = os.path.getsize(partial)
    check(0 < size < os.path.getsize(os.path.join(REAL, "comet-2019-222-02-154.dbd")),
          "the partial (%d bytes) stays in .incoming/" % size)
    # Next call: Zmodem resumes the cut file; it is published whole.
    run_glider(shore.port, "unit_346", card, work)
    ev2 = wait_for_events(root, "unit_346", 2)[1]
    shore.stop()
    got = os.path.join(root, "unit_346", "from-glider", "comet-2019-222-02-154.dbd")
    check(os.path.exists(got) and sha(got) == sha(os.path.join(REAL, "comet-2019-222-02-154.dbd")),
          "next call: the file is resumed and published byte-identical")
    check(ev2["partial_files"] == [] and os.path.exists(got + ".csv"), "no partial left, CSV written")
    journal = check_journal(os.path.join(root, "unit_346", "logs", ev2["journal"]))
    m = [re.search(r"zmodem receive: (\d+) bytes in", l) for l in journal]
    bytes_in = [int(x.group(1)) for x in m if x]
    check(bytes_in and bytes_in[0] < os.path.getsize(got) - size + 300000,
          "the resumed call moved fewer bytes than a full resend (%s)" % bytes_in)


def scenario_two_gliders(exe, work):
    root = os.path.join(work, "root")
    shore = Shore(exe, root, "--max-calls", "4")
    cards = {"unit_401": make_card(work, "unit_401", ["comet-2019-222-02-154.dbd"]),
             "unit_402": make_card(work, "unit_402", ["comet-2019-222-02-156.dbd"])}
    procs = {}
    for name, card in cards.items():
        procs[name] = subprocess.Popen(FAKE + ["--port", str(shore.port), "--name", name, "--files", card,
                                               "--inbox", os.path.join(work, name + "-inbox")])
    starts = {}
    for name, proc in procs.items():
        proc.wait(timeout=45)
        starts[name] = wait_for_events(root, name, 1)[0]
    shore.stop()
    for name, real in [("unit_401", "comet-2019-222-02-154.dbd"), ("unit_402", "comet-2019-222-02-156.dbd")]:
        got = os.path.join(root, name, "from-glider", real)
        check(os.path.exists(got) and sha(got) == sha(os.path.join(REAL, real)), "%s got its own file" % name)
        other = "comet-2019-222-02-156.dbd" if name == "unit_401" else "comet-2019-222-02-154.dbd"
        check(not os.path.exists(os.path.join(root, name, "from-glider", other)), "%s did not get the other's" % name)
    a, b = starts["unit_401"], starts["unit_402"]
    overlap = a["call_start_utc"] <= b["call_end_utc"] and b["call_start_utc"] <= a["call_end_utc"]
    check(overlap, "the two calls were served at the same time")


def scenario_busy(exe, work):
    root = os.path.join(work, "root")
    card = make_card(work, "unit_600", [])
    shore = Shore(exe, root, "--max-calls", "2")
    # Both calls stay open (idle hang-up after 8 s and 6 s) while the third comes.
    first = subprocess.Popen(FAKE + ["--port", str(shore.port), "--name", "unit_600", "--files", card,
                                     "--idle-hangup", "8"])
    wait_for_file = os.path.join(root, "unit_600", "logs")
    for _ in range(100):
        if os.path.isdir(wait_for_file) and os.listdir(wait_for_file):
            break
        time.sleep(0.05)
    # The same glider calls again while its first call is still open (a dead
    # call not yet noticed): the second call is served but leaves the queue alone.
    subprocess.check_call([exe, "--root", root, "queue", "unit_600", "--command", "put u_y 1"])
    second = subprocess.Popen(FAKE + ["--port", str(shore.port), "--name", "unit_600", "--files", card,
                                      "--idle-hangup", "6", "--record", os.path.join(work, "second.jsonl")])
    time.sleep(0.5)
    # A third call is over --max-calls: closed at once, no folder, no event.
    start = time.time()
    third_record = os.path.join(work, "third.jsonl")
    subprocess.run(FAKE + ["--port", str(shore.port), "--name", "unit_601", "--files", card,
                           "--record", third_record], capture_output=True, timeout=30)
    typed = [json.loads(l) for l in open(third_record)] if os.path.exists(third_record) else []
    check(typed == [] and not os.path.exists(os.path.join(root, "unit_601")),
          "a call over --max-calls is closed unserved (in %.1f s, nothing typed, no folder)" % (time.time() - start))
    second.wait(timeout=30)
    first.wait(timeout=30)
    evs = wait_for_events(root, "unit_600", 2)
    shore.stop()
    second_said = [json.loads(l)["command"] for l in open(os.path.join(work, "second.jsonl")) if "command" in l]
    check(second_said == ["whoru"], "the second call of the same glider only asked whoru: %s" % second_said)
    check(any("another call of this glider" in n for e in evs for n in e["notes"]), "its event says why")
    check(open(os.path.join(root, "unit_600", "commands.queue")).read() == "put u_y 1\n",
          "the command queued meanwhile waits for the next call")
    check("refused" in open(root + ".stderr").read(), "the refusal is in the shore's log")


def scenario_garbage(exe, work):
    root = os.path.join(work, "root")
    card = make_card(work, "unit_500", ["comet-2019-222-02-155.dbd"])
    shore = Shore(exe, root, "--max-line", "1024")
    rc, said = run_glider(shore.port, "unit_500", card, work, "--garbage")
    ev = wait_for_events(root, "unit_500", 1)[0]
    shore.stop()
    check(ev["gps"] is not None and [f["name"] for f in ev["files_received"]][-1] == "comet-2019-222-02-155.dbd",
          "after junk bytes and a 100 kB line the dialog is still read and files fetched")
    lines = check_journal(os.path.join(root, "unit_500", "logs", ev["journal"]))
    check(any("\\x00\\xFF\\x1B" in l for l in lines), "junk bytes journaled as \\xNN")
    check(any("line cut: 98976 more bytes dropped" in l for l in lines) and max(len(l) for l in lines) < 1100,
          "the overlong line was cut at --max-line and its rest counted")


def scenario_unidentified(exe, work):
    root = os.path.join(work, "root")
    card = make_card(work, "anon", [])
    shore = Shore(exe, root, "--identify-timeout", "2")
    start = time.time()
    rc, said = run_glider(shore.port, "anon", card, work, "--no-name", "--idle-hangup", "30")
    took = time.time() - start
    shore.stop()
    check(took < 10, "a glider that never says its name is dropped after the timeout (%.1f s)" % took)
    check([l.get("command") for l in said if "command" in l][:3] == ["whoru"] * 3, "the shore asked whoru 3 times")
    check(sorted(f for f in os.listdir(root) if not f.endswith((".port", ".stderr"))) == ["unidentified"],
          "no glider folder was made: %s" % os.listdir(root))
    journals = glob.glob(os.path.join(root, "unidentified", "*.journal"))
    lines = check_journal(journals[0])
    check(any("end: not identified within 2 s" in l for l in lines), "its journal is in unidentified/ with the reason")
    # A glider that names itself in its dialog but hangs up before any prompt:
    # its position still makes an event.
    shore = Shore(exe, root)
    run_glider(shore.port, "unit_700", card, work, "--hangup-after-dialog")
    ev = wait_for_events(root, "unit_700", 1)[0]
    shore.stop()
    check(ev["end_reason"] == "hangup before identification" and ev["gps"]["lat_ddmm"] == 4319.4 and
          ev["commands_sent"] == [], "a call cut before the prompt still gives an event with the fix")


def scenario_dialog(exe, work):
    text = open(os.path.join(HERE, "data", "surface_dialog.txt")).read().replace("@NAME@", "unit_345")
    path = os.path.join(work, "dialog.txt")
    with open(path, "w") as f:
        f.write(text + "junk line\nGPS Location:  nan N 00726.900 E measured 1.0 secs ago\nGliderDos A 8 >\n")
    report = json.loads(subprocess.check_output([exe, "dialog", path]))
    check(report["vehicle_name"] == "unit_345" and report["mission"]["name"] == "goto_l10.mi",
          "dialog: name and mission")
    check(report["gps"]["lat_ddmm"] == 4319.4 and report["unparsed_lines"] == 1,
          "dialog: a NaN fix is refused (the earlier valid one stays), counted as unparsed")
    check(report["prompt"] == "GliderDos A 8 >", "dialog: the abort prompt")
    bad = subprocess.run([exe, "--root", os.path.join(work, "r"), "queue", "../etc", "--command", "x"],
                         capture_output=True)
    check(bad.returncode == 1 and b"glider name" in bad.stderr, "queue refuses a glider name that is not a plain name")
    usage = subprocess.run([exe, "--root", os.path.join(work, "r"), "queue", "unit_1"], capture_output=True)
    check(usage.returncode == 2, "queue with nothing to queue is a usage error")
    listen = subprocess.run([exe, "--root", os.path.join(work, "r"), "serve", "--listen", "999.1.1.1"],
                            capture_output=True, timeout=10)
    check(listen.returncode == 1 and b"--listen 999.1.1.1: not an IPv4 or IPv6 address" in listen.stderr,
          "serve refuses a bad --listen address, naming it")


def main():
    exe, scenario, work = sys.argv[1], sys.argv[2], sys.argv[3]
    if scenario != "dialog" and not (shutil.which("sz") and shutil.which("rz")):
        print("SKIPPED: Debian's lrzsz (sz/rz) is not installed (./glider doctor)")
        sys.exit(77)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    atexit.register(kill_leftovers)
    globals()["scenario_" + scenario](exe, work)
    print("PASS " + scenario)


if __name__ == "__main__":
    main()
