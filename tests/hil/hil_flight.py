#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Hardware in the loop: the real glider-firmware binary, started as its
systemd unit starts it (--board, --mission; plus the bench-only
--time-scale), flies against glider-plant over its real interfaces; the same
mission, vehicle, seed (and the matching fault) is flown by glider-sil; the
two flight logs are compared event by event within stated tolerances
(docs/hil.md, "Tolerances").

  hil_flight.py BUILD_DIR SOURCE_DIR CASE [--time-scale X] [--keep DIR]
  hil_flight.py BUILD_DIR SOURCE_DIR CASE --compare DIR   (the flights a --keep
      kept, compared again: the same flights under another rule; no drop weight)

CASE is one of CASES below. Prints the SIL-vs-HIL table and the firmware's
loop wake-up lateness; "PASS hil CASE" or "FAIL hil CASE: why", or, when the
flight failed on an actuator-fault abort that the plant's own record shows
it caused by answering late (an overloaded machine: overload_verdict.py),
"SKIP hil CASE: overloaded, not judged" with the evidence, exit 77.
GLIDER_FIRMWARE / GLIDER_FIRMWARE_PREFIX run another build of the firmware
(the arm64 one under "qemu-aarch64 -L /": ./glider cross runs every case so).
"""
import argparse
import csv
import glob
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import overload_verdict
import start_fix

VEHICLE = "boards/vehicles/slocum_we01.toml"
SEED = 1

# name: mission, plant faults, the matching glider-sil faults, what must happen.
#   end: "complete" (the firmware finishes and exits by itself) or "abort"
#   (the firmware aborts; the harness stops it once it has shown the abort)
CASES = {
    # The Slocum mission: a fix at launch, yos to a waypoint, a surfacing
    # with a fix and the dead-reckoning error, the mission's end.
    # goto: its waypoints and arrival radius, for the start-fix correction (start_fix.py).
    "waypoint": dict(mission="tests/hil/waypoint/missions/hil.mi", plant=[], sil=[], end="complete",
                     goto="tests/hil/waypoint/mafiles/goto_l10.ma"),
    "yo": dict(mission="tests/hil/short_yo.toml", plant=[], sil=[], end="complete"),
    # The pump jams just after the first inflection at depth: its drive
    # reports the stall and it moves no more (SIL: a fault flag and a stuck pump).
    "pump_stall": dict(mission="tests/hil/short_yo.toml", plant=["pump_stall@125s"],
                       sil=["pump_fault@125s", "pump_stuck@125s"], end="abort", cause=5),
    # A silent transmitter makes each cycle wait its timeouts in wall time
    # (the board's [depth] response_timeout_ms 100 x (1 + retries 1)): the
    # row that shows the abort is stamped that much later (times the scale).
    "depth_silent": dict(mission="tests/hil/short_yo.toml", plant=["depth_silent@60s"], sil=["depth_invalid@60s"],
                         end="abort", cause=3, blocked_wall_s=0.2),
    "compass_silent": dict(mission="tests/hil/short_yo.toml", plant=["compass_silent@60s"],
                           sil=["attitude_frozen@60s"], end="abort", cause=4),
    # Power lost mid-flight: every device silent. Not compared with SIL for
    # its time (the firmware's loop slows to the Modbus timeouts, wall time);
    # it must abort on an actuator or sensor fault and keep cycling.
    "plant_silent": dict(mission="tests/hil/short_yo.toml", plant=["plant_silent@60s"], sil=None, end="abort",
                         cause=(3, 4, 5)),
    # The plant process dies (SIGKILL) about a simulated minute into the
    # flight: connection refused, ptys hung up. The same demand.
    "plant_killed": dict(mission="tests/hil/short_yo.toml", plant=[], kill_plant_at_s=60.0, sil=None, end="abort",
                         cause=(3, 4, 5)),
    # The overload verdict itself (overload_verdict.py), each flown once: the
    # harness stops (SIGSTOP) the plant for 0.5 s of wall time a simulated
    # minute in, longer than the firmware's three 110 ms attempts: the flight
    # aborts on an actuator fault that the plant caused, and must be judged
    # "overloaded, not judged". And the pump jammed by the plant while SIL's
    # is not: an actuator fault with a prompt plant, which must FAIL.
    "plant_paused": dict(mission="tests/hil/short_yo.toml", plant=[], pause_plant=(60.0, 0.5), sil=[], end="abort",
                         cause=5, verdict="overloaded"),
    "actuator_fault_prompt": dict(mission="tests/hil/short_yo.toml", plant=["pump_stall@125s"], sil=[], end="abort",
                                  cause=5, verdict="fail"),
}

ABORT_NAMES = {0: "none", 1: "overdepth", 2: "overtime", 3: "depth sensor", 4: "attitude sensor", 5: "actuator fault",
               6: "leak", 7: "low battery", 8: "samedepth", 9: "stalled", 10: "waypoint too far"}
PHASE_NAMES = {0: "surface", 1: "dive", 2: "climb", 99: "abort"}

PROCESSES = []


def fail(case, message):
    print("FAIL hil %s: %s" % (case, message))
    for p in PROCESSES:
        if p.poll() is None:
            p.kill()
    sys.exit(1)


def number(text):
    try:
        return float(text) if text != "" else None
    except ValueError:
        return None


def read_log(path):
    """Rows as dicts of numbers, with "t": simulated seconds since the first
    row. A target log's m_present_time is the loop clock told in UTC ("# time:
    m_present_time is the loop clock told in UTC ..."): simulated seconds
    already. An older target log stamped rows with the wall clock and says
    its loop's time scale in a "# time_scale: X" line; its times are scaled
    back."""
    with open(path) as f:
        text = f.readlines()
    lines = [line for line in text if not line.startswith("#")]
    scale = 1.0
    loop_time = any(re.match(r"#\s*time:.*loop clock told in UTC", line) for line in text)
    for line in text:
        m = re.match(r"#\s*time_scale:\s*([0-9.eE+-]+)", line)
        if m and not loop_time:
            scale = float(m.group(1))
    rows = [{k: number(v) for k, v in row.items()} for row in csv.DictReader(lines)]
    t0 = rows[0]["m_present_time"]
    for row in rows:
        row["t"] = (row["m_present_time"] - t0) * scale
    return rows


def events(rows):
    """What the firmware did, from its log: phase changes (time, phase, depth),
    yo count, abort cause and time, waypoint arrivals (and the dive each
    started from: its time and the DR's start, the fix, in that row), DR
    errors at surfacings."""
    e = dict(phases=[], yos=0, abort=0, abort_t=None, waypoints=[], arrivals=[], dr=[], end_t=rows[-1]["t"],
             max_depth=0.0, navigation="x_waypoints_reached" in rows[0] and "x_dr_error_m" in rows[0])
    last_phase = None
    last_reached = 0
    dive = dict(dive_t=None, start=None)
    for row in rows:
        phase = int(row["m_depth_state"])
        if phase != last_phase:
            e["phases"].append((row["t"], phase, row["m_depth"]))
            if phase == 1 and last_phase == 0:  # a dive from the surface: the DR restarts from the last fix
                has_start = row.get("m_lat") is not None and row.get("m_lon") is not None
                dive = dict(dive_t=row["t"], start=(row["m_lat"], row["m_lon"]) if has_start else None)
            last_phase = phase
        e["yos"] = int(row["x_yo_count"])
        if row["x_abort_cause"] and e["abort_t"] is None:
            e["abort"] = int(row["x_abort_cause"])
            e["abort_t"] = row["t"]
        if row["m_depth"] is not None and e["abort_t"] is None:
            e["max_depth"] = max(e["max_depth"], row["m_depth"])
        reached = int(row.get("x_waypoints_reached") or 0)
        if reached > last_reached:
            e["waypoints"].append(row["t"])
            e["arrivals"].append(dict(t=row["t"], **dive))
            last_reached = reached
        if row.get("x_dr_error_m") is not None:
            e["dr"].append((row["t"], row["x_dr_error_m"]))
    return e


class Table:
    def __init__(self):
        self.rows = []
        self.failures = []
        self.missing = []

    def add(self, what, sil, hil, ok, tolerance):
        self.rows.append((what, sil, hil, tolerance, "ok" if ok else "FAIL"))
        if not ok:
            self.failures.append(what)

    def compare(self, what, sil, hil, tolerance, unit="", sil_shown=None):
        """hil within tolerance of sil (the SIL column shows sil_shown when given)."""
        if sil is None or hil is None:
            self.add(what, sil, hil, sil is None and hil is None, "both absent")
            return
        self.add(what, sil_shown or "%.1f%s" % (sil, unit), "%.1f%s" % (hil, unit), abs(sil - hil) <= tolerance,
                 "+-%.1f%s" % (tolerance, unit))

    def print(self):
        print("| %-28s | %-14s | %-14s | %-12s | %-4s |" % ("", "SIL", "HIL", "tolerance", ""))
        print("|" + "|".join("-" * n for n in (30, 16, 16, 14, 6)) + "|")
        for r in self.rows:
            print("| %-28s | %-14s | %-14s | %-12s | %-4s |" % tuple(str(x) for x in r))


def time_tolerance(t):
    """Event times: the firmware samples the plant at other instants than SIL
    (serial and Modbus latency, wake-up lateness times the time scale) and its
    sensor noise is drawn in another order, so a threshold crossing may fall
    one or two 1 s cycles apart, and a glide's small speed difference grows
    with time: 3 s plus 2 % of the elapsed time."""
    return 3.0 + 0.02 * t


def compare(sil, hil, case, table, scale, source):
    # A cycle blocked on a silent device, in simulated seconds.
    blocked = case.get("blocked_wall_s", 0.0) * scale
    table.add("phase sequence", "-".join(PHASE_NAMES[p] for _, p, _ in sil["phases"]),
              "-".join(PHASE_NAMES[p] for _, p, _ in hil["phases"]),
              [p for _, p, _ in sil["phases"]] == [p for _, p, _ in hil["phases"]], "equal")
    for i, ((ts, ps, ds), (th, ph, dh)) in enumerate(zip(sil["phases"][1:], hil["phases"][1:])):
        table.compare("%d: %s at, s" % (i + 1, PHASE_NAMES[ps]), ts, th,
                      time_tolerance(ts) + (blocked if ps == 99 else 0.0))
        if ps in (1, 2) and ds is not None and dh is not None:
            # Inflection depths: one cycle's travel at ~0.25 m/s, plus the noise.
            table.compare("%d: %s from depth, m" % (i + 1, PHASE_NAMES[ps]), ds, dh, 0.5)
    table.add("yos", sil["yos"], hil["yos"], sil["yos"] == hil["yos"], "equal")
    table.add("abort cause", ABORT_NAMES[sil["abort"]], ABORT_NAMES[hil["abort"]], sil["abort"] == hil["abort"],
              "equal")
    if sil["abort_t"] is not None or hil["abort_t"] is not None:
        table.compare("abort at, s", sil["abort_t"], hil["abort_t"], time_tolerance(sil["abort_t"] or 0.0) + blocked)
    table.compare("max depth before abort/end, m", sil["max_depth"], hil["max_depth"], 0.5)
    if not hil["navigation"] and (sil["waypoints"] or sil["dr"]):
        # The log of an older target has no navigation columns: said, not passed.
        table.missing.append("x_waypoints_reached and x_dr_error_m (not in the HIL log)")
        table.add("waypoints reached", len(sil["waypoints"]), "not logged", True, "equal")
        table.add("surfacings with DR error", len(sil["dr"]), "not logged", True, "equal")
        if case["end"] == "complete":
            table.compare("mission complete at, s", sil["end_t"], hil["end_t"], time_tolerance(sil["end_t"]))
        return
    table.add("waypoints reached", len(sil["waypoints"]), len(hil["waypoints"]),
              len(sil["waypoints"]) == len(hil["waypoints"]), "equal")
    goto = start_fix.read_goto(os.path.join(source, case["goto"])) if "goto" in case else None
    for i, (ts, th) in enumerate(zip(sil["arrivals"], hil["arrivals"])):
        expected = None
        if goto and ts["dive_t"] is not None and th["dive_t"] is not None:
            waypoints, radius = goto
            expected = start_fix.expected_arrival(ts, th, waypoints[i % len(waypoints)], radius)
        if expected is None:
            table.compare("waypoint %d reached at, s" % (i + 1), ts["t"], th["t"], time_tolerance(ts["t"]))
            continue
        # The dive may start from another GPS epoch's fix than SIL's (start_fix.py): the arrival is
        # compared with SIL's shifted by HIL's own dive time and distance to go at SIL's approach speed.
        table.add("waypoint %d: dive, to go" % (i + 1), "%.0f s, %.1f m" % (ts["dive_t"], expected["d_sil"]),
                  "%.0f s, %.1f m" % (th["dive_t"], expected["d_hil"]), True,
                  "at %.3f m/s" % expected["speed"])
        table.compare("waypoint %d reached at, s" % (i + 1), expected["t"], th["t"], time_tolerance(ts["t"]),
                      sil_shown="%.1f (%.1f)" % (ts["t"], expected["t"]))
    table.add("surfacings with DR error", len(sil["dr"]), len(hil["dr"]), len(sil["dr"]) == len(hil["dr"]), "equal")
    for i, ((_, es), (_, eh)) in enumerate(zip(sil["dr"], hil["dr"])):
        # GPS noise 3 m (1 sigma per axis) on each of the two fixes that bound
        # the dead-reckoned leg, drawn at other instants in HIL: 4 sigma of
        # the difference of two such errors, 4 * 3 m * sqrt(2) * sqrt(2) = 24 m.
        table.compare("surfacing %d DR error, m" % (i + 1), es, eh, 24.0)
    if case["end"] == "complete":
        table.compare("mission complete at, s", sil["end_t"], hil["end_t"], time_tolerance(sil["end_t"]))


def compare_drop_weight(sil_summary, firmware_stderr, case, table):
    """The drop weight through the shipped paths: the vehicle file's [fitted]
    in SIL (slocum_we01: drop_weight = true, released by every abort), the
    board file on the target. The plant's board has no [gpio] (no GPIO chip
    without a kernel), so the firmware must say its weight is not fitted:
    what the board file says, not what SIL flew."""
    abort = sil_summary["abort"]
    sil_released = abort is not None and abort["drop_weight_released"]
    m = re.findall(r"glider-firmware: drop weight: (.*)", firmware_stderr)
    hil_said = m[-1] if m else "not said"
    table.add("drop weight (SIL: vehicle file)", "released" if sil_released else "kept",
              "(board)", sil_released == (case["end"] == "abort"), "abort releases")
    table.add("drop weight (HIL: board file)", "fitted (vehicle)", hil_said,
              hil_said == "not fitted (the board has no [gpio])", "board decides")


def start(args, **kwargs):
    p = subprocess.Popen(args, **kwargs)
    PROCESSES.append(p)
    return p


def run_sil(build, source, case, tmp):
    """The SIL flight's log rows and its summary (docs/sil-summary.md)."""
    log = os.path.join(tmp, "sil.csv")
    summary = os.path.join(tmp, "sil.json")
    args = [os.path.join(build, "sil", "glider-sil"), "--vehicle", VEHICLE, "--mission", case["mission"],
            "--seed", str(SEED), "--out", log, "--summary-json", summary, "--quiet"]
    for f in case["sil"]:
        args += ["--fault", f]
    result = subprocess.run(args, cwd=source, capture_output=True, text=True, timeout=60)
    if result.returncode not in (0, 2, 3):
        raise RuntimeError("glider-sil failed (%d): %s" % (result.returncode, result.stderr))
    with open(summary) as f:
        return read_log(log), json.load(f)


def firmware_binary(build):
    for candidate in ("firmware/linux/glider-firmware", "target/glider-firmware"):
        path = os.path.join(build, candidate)
        if os.path.exists(path):
            return path
    return os.path.join(build, "firmware/linux/glider-firmware")


def lateness(stderr):
    m = re.findall(r"loop: (cycles \d+, wake-up late mean \d+ us, p50 <= \d+ us, p99 <= \d+ us, max \d+ us[^;]*)",
                   stderr)
    return m[-1] if m else None


def run_hil(build, source, name, case, tmp, scale, stop_s, compass_interval_s=None):
    """Flies the case; the firmware ends by itself or gets SIGTERM at `stop_s`
    simulated seconds (a wall-time bound with a margin for a loaded machine).
    Returns the log's rows, the firmware's stderr, whether the harness
    stopped it, and the problems seen (for the verdict: main())."""
    # A flight to its end gets 30 % and 10 s more (a loaded machine, start-up);
    # an abort case only needs its minute after the abort, plus start-up.
    limit_s = stop_s / scale * 1.3 + 10.0 if case["end"] == "complete" else stop_s / scale + 3.0
    plant_dir = os.path.join(tmp, "plant")
    plant_args = [os.path.join(build, "tools", "hardware", "plant", "glider-plant"), "--dir", plant_dir, "--vehicle", VEHICLE,
                  "--seed", str(SEED), "--time-scale", str(scale), "--duration-s", str((limit_s + 30.0) * scale),
                  "--truth", os.path.join(plant_dir, "truth.csv")]  # kept with the flight (--keep): inflection_dr.py
    for f in case["plant"]:
        plant_args += ["--fault", f]
    if compass_interval_s is not None:
        plant_args += ["--compass-interval-s", str(compass_interval_s)]
    plant = start(plant_args, cwd=source, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    ready = plant.stdout.readline()
    if "glider-plant: ready" not in ready:
        fail(name, "the plant did not start: " + ready + plant.stdout.read())
    print(ready, end="")
    board = os.path.join(plant_dir, "board.toml")
    # As the systemd unit starts it (firmware/linux/packaging/glider-firmware.service),
    # plus the bench-only time scale.
    prefix = os.environ.get("GLIDER_FIRMWARE_PREFIX", "").split()
    firmware = os.environ.get("GLIDER_FIRMWARE", firmware_binary(build))
    fw_args = prefix + [firmware, "--board", board, "--mission", os.path.join(source, case["mission"]),
                        "--time-scale", str(scale)]
    print("$ " + " ".join(fw_args))
    started = time.monotonic()
    fw = start(fw_args, stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
    stopped_by_us = False
    killed = False
    paused = False
    while fw.poll() is None:
        if "pause_plant" in case and not paused and time.monotonic() - started > case["pause_plant"][0] / scale:
            # As an overloaded machine does to it: the plant is not scheduled for a while.
            plant.send_signal(signal.SIGSTOP)
            time.sleep(case["pause_plant"][1])
            plant.send_signal(signal.SIGCONT)
            paused = True
            print("harness: glider-plant paused (SIGSTOP) %.1f s of wall time, %.1f s after the firmware started" %
                  (case["pause_plant"][1], time.monotonic() - started - case["pause_plant"][1]))
        if "kill_plant_at_s" in case and not killed and time.monotonic() - started > case["kill_plant_at_s"] / scale:
            plant.kill()  # the firmware starts within a fraction of a simulated second: near enough
            killed = True
            print("harness: glider-plant killed (SIGKILL) %.1f s after the firmware started" %
                  (time.monotonic() - started))
        if time.monotonic() - started > limit_s:
            fw.send_signal(signal.SIGTERM)
            stopped_by_us = True
            break
        time.sleep(0.1)
    try:
        _, err = fw.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        fail(name, "glider-firmware did not stop within 10 s of SIGTERM (a hang)")
    wall = time.monotonic() - started
    if not killed:
        plant.send_signal(signal.SIGTERM)
    plant_out, _ = plant.communicate(timeout=10)
    print(plant_out, end="")
    print(err, end="")
    print("firmware ran %.1f s wall (%s)" % (wall, "stopped by the harness" if stopped_by_us else "exited itself"))
    problems = []
    # 0: mission done or stopped by SIGTERM; 3: the flight ended in an abort.
    if fw.returncode not in ((0,) if case["end"] == "complete" else (0, 3)):
        problems.append("glider-firmware exit status %d" % fw.returncode)
    logs = glob.glob(os.path.join(plant_dir, "logs", "flight-*.csv"))
    if len(logs) != 1:
        fail(name, "; ".join(problems + ["expected one flight log in %s, found %d" % (plant_dir, len(logs))]))
    return read_log(logs[0]), err, stopped_by_us, problems


def overloaded(hil, plant_dir, scale):
    """overload_verdict.judge on this flight: (overloaded, evidence lines)."""
    record = os.path.join(plant_dir, "lateness.csv")
    if not os.path.exists(record):
        return False, ["no plant lateness record (%s)" % record]
    response_timeout_ms, cycle_budget_ms = overload_verdict.read_bus(plant_dir)
    return overload_verdict.judge(hil["abort"], hil["abort_t"], overload_verdict.read_record(record),
                                  response_timeout_ms, cycle_budget_ms, scale)


def conclude(name, case, problems, hil, plant_dir, scale):
    """The verdict: PASS, FAIL, or (a failure on an actuator-fault abort the
    plant's lateness caused) SKIP "overloaded, not judged", exit 77. A case
    with "verdict" checks the rule itself: it passes when the rule gives that
    verdict."""
    judged = overloaded(hil, plant_dir, scale) if problems else (False, [])
    is_overloaded, evidence = judged
    if problems:
        print("the flight failed (%s); overload verdict:" % "; ".join(problems))
        for line in evidence:
            print("  " + line)
    want = case.get("verdict")
    if want == "overloaded":
        if problems and is_overloaded:
            print("PASS hil %s: the paused plant's abort is judged overloaded, not judged" % name)
            sys.exit(0)
        fail(name, "expected the overloaded verdict, got %s" % ("a failure without the plant's evidence"
                                                                if problems else "a flight that passed"))
    if want == "fail":
        if problems and is_overloaded:
            print("SKIP hil %s: the plant answered late at the fault (an overloaded machine): the prompt-plant "
                  "verdict cannot be shown" % name)
            sys.exit(77)
        if problems and hil["abort"] == overload_verdict.ACTUATOR_FAULT:
            print("PASS hil %s: an actuator fault with a prompt plant fails" % name)
            sys.exit(0)
        fail(name, "expected an actuator-fault failure with a prompt plant, got %s" %
             ("; ".join(problems) if problems else "a flight that passed"))
    if not problems:
        return
    if is_overloaded:
        print("SKIP hil %s: overloaded, not judged: %s" % (name, "; ".join(problems)))
        sys.exit(77)
    fail(name, "; ".join(problems))


def compare_kept(directory, source, name, case, scale):
    """The SIL and HIL logs a --keep kept, compared as a flight compares them (no drop weight: the firmware's
    stderr is not kept)."""
    logs = glob.glob(os.path.join(directory, "plant", "logs", "flight-*.csv"))
    if case["sil"] is None or len(logs) != 1:
        fail(name, "%s: a kept SIL log and one HIL log wanted (%d found)" % (directory, len(logs)))
    sil_rows, hil = read_log(os.path.join(directory, "sil.csv")), events(read_log(logs[0]))
    if case["end"] != "complete":  # the harness stopped the HIL flight: the same stretch of time
        sil_rows = [r for r in sil_rows if r["t"] <= hil["end_t"]]
    table = Table()
    compare(events(sil_rows), hil, case, table, scale, source)
    print("SIL vs HIL, case %s, kept in %s:" % (name, directory))
    table.print()
    conclude(name, case, ["outside tolerance: " + ", ".join(table.failures)] if table.failures else [], hil,
             os.path.join(directory, "plant"), scale)
    print("PASS hil %s" % name)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("source")
    parser.add_argument("case", choices=sorted(CASES))
    parser.add_argument("--time-scale", type=float, default=20.0)
    parser.add_argument("--keep", help="keep the logs in this directory")
    parser.add_argument("--compare", help="compare the flights kept (--keep) in this directory again, fly nothing")
    parser.add_argument("--compass-interval-s", type=float,
                        help="glider-plant --compass-interval-s (default: the plant's, every model step)")
    a = parser.parse_args()
    build, source = os.path.abspath(a.build), os.path.abspath(a.source)
    case = CASES[a.case]
    if a.compare:
        compare_kept(a.compare, source, a.case, case, a.time_scale)
        return
    prefix = os.environ.get("GLIDER_FIRMWARE_PREFIX", "").split()
    firmware = os.environ.get("GLIDER_FIRMWARE", firmware_binary(build))
    if "GLIDER_FIRMWARE" in os.environ and not os.access(firmware, os.X_OK):
        fail(a.case, "GLIDER_FIRMWARE=%s is not an executable file" % firmware)
    probe = subprocess.run(prefix + [firmware, "--help"], capture_output=True, text=True, timeout=60)
    if probe.returncode != 0 and ("GLIDER_FIRMWARE" in os.environ or prefix):
        # Another build asked for by name (the arm64 one in ./glider cross) must run, not be skipped.
        fail(a.case, "%s --help exited %d: %s" % (" ".join(prefix + [firmware]), probe.returncode, probe.stderr[-500:]))
    usage = probe.stdout
    if "--time-scale" not in usage:
        print("SKIP hil %s: %s has no --time-scale (the bench option of issue 12 item 3)" % (a.case, firmware))
        sys.exit(77)
    tmp = tempfile.mkdtemp(prefix="hil-")
    try:
        sil_rows, sil_summary = run_sil(build, source, case, tmp) if case["sil"] is not None else (None, None)
        sil = events(sil_rows) if sil_rows else None
        if case["end"] == "complete":
            stop_s = sil["end_t"]
        else:  # a minute after the abort, to see the firmware go on cycling
            fault_s = (case.get("kill_plant_at_s") or case.get("pause_plant", (None,))[0] or
                       min(float(f.split("@")[1].rstrip("s")) for f in case["plant"]))
            stop_s = (sil["abort_t"] if sil and sil["abort_t"] is not None else fault_s) + 60.0
        hil_rows, err, stopped, problems = run_hil(build, source, a.case, case, tmp, a.time_scale, stop_s,
                                                   a.compass_interval_s)
        hil = events(hil_rows)
        if sil is not None and stopped:
            # The harness stopped the HIL flight: compare the same stretch of time.
            sil = events([r for r in sil_rows if r["t"] <= hil["end_t"]])
        print("loop lateness at time scale %g: %s" % (a.time_scale, lateness(err)))
        if case["end"] == "complete" and stopped:
            problems.append("the firmware did not complete the mission within the wall-time bound")
        missing = []
        if sil is not None:
            table = Table()
            compare(sil, hil, case, table, a.time_scale, source)
            compare_drop_weight(sil_summary, err, case, table)
            print("SIL vs HIL, case %s (mission %s, vehicle %s, seed %d, time scale %g):" %
                  (a.case, case["mission"], VEHICLE, SEED, a.time_scale))
            table.print()
            if table.failures:
                problems.append("outside tolerance: " + ", ".join(table.failures))
            missing = table.missing
        if sil is None:  # no table: the board's drop weight checked alone
            said = re.findall(r"glider-firmware: drop weight: (.*)", err)
            if not said or said[-1] != "not fitted (the board has no [gpio])":
                problems.append("the firmware said drop weight: %s (the plant's board has no [gpio])" %
                                (said[-1] if said else "nothing"))
        if case["end"] == "abort":
            causes = case["cause"] if isinstance(case["cause"], tuple) else (case["cause"],)
            if hil["abort"] not in causes:
                problems.append("abort cause %s, expected %s" %
                                (ABORT_NAMES[hil["abort"]], " or ".join(ABORT_NAMES[c] for c in causes)))
            else:
                after = [r for r in hil_rows if r["t"] > hil["abort_t"]]
                if stopped and len(after) < 3:
                    problems.append("the firmware stopped cycling after the abort (%d rows after it)" % len(after))
                print("abort %s at %.1f s; %s" % (ABORT_NAMES[hil["abort"]], hil["abort_t"],
                      "the firmware kept cycling: %d log rows after it" % len(after) if stopped
                      else "the firmware knew it was up and ended the flight"))
        conclude(a.case, case, problems, hil, os.path.join(tmp, "plant"), a.time_scale)
        if missing:
            print("SKIP hil %s: all else within tolerance, but cannot compare %s" % (a.case, "; ".join(missing)))
            sys.exit(77)
    finally:
        if a.keep:
            shutil.copytree(tmp, a.keep, dirs_exist_ok=True)
        shutil.rmtree(tmp, ignore_errors=True)
    print("PASS hil %s" % a.case)


if __name__ == "__main__":
    main()
