#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The waypoint comparison of hil_flight.py with the start-fix correction
(start_fix.py, docs/hil.md "The launch fix"), on event records built here:
- the failure of the arm64 proof (HIL dove a second later from the next
  epoch's fix, 3.6 m further east, and arrived at 383 s against SIL's 395 s)
  passes: the fix explains 10 of the 12 s;
- the same dive with a waypoint 10 m nearer (the firmware flying a wrong
  waypoint: arrival 30 s early from SIL's own fix) fails, and so do an
  arrival 12 s late from SIL's fix and a wrong fix that would need more
  than the tolerance;
- the goto file's bad input names the file and the line.
  check_start_fix.py SOURCE_DIR"""
import math
import os
import sys
import tempfile

source = os.path.abspath(sys.argv[1])
sys.path.insert(0, os.path.join(source, "tests", "hil"))
import bad_input  # noqa: E402
import hil_flight  # noqa: E402
import start_fix  # noqa: E402

failures = []


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAIL", what))
    if not ok:
        failures.append(what)


WAYPOINTS, RADIUS = start_fix.read_goto(os.path.join(source, hil_flight.CASES["waypoint"]["goto"]))
check(len(WAYPOINTS) == 1 and RADIUS == 30.0, "the goto file: 1 waypoint, radius 30 m (%d, %g)" %
      (len(WAYPOINTS), RADIUS))
LAUNCH = (5418.966, 724.588)  # the SIL's launch point (the mission file's comment)
M_PER_MIN_LAT = 1852.0
M_PER_MIN_LON = 1852.0 * math.cos(math.radians(start_fix.degrees(LAUNCH[0])))


def at(east_m, north_m):
    """A (lat, lon) ddmm.mmmm point east/north of the launch point (whole minutes stay put here)."""
    return (LAUNCH[0] + north_m / M_PER_MIN_LAT, LAUNCH[1] + east_m / M_PER_MIN_LON)


def flight(dive_t, start, arrival_t, end_t=463.0):
    """Event records as hil_flight.events gives them, for the waypoint mission's shape."""
    phases = [(0.0, 0, 0.1), (dive_t, 1, 0.1), (140.0, 2, 20.2), (227.0, 1, 5.0), (316.0, 2, 20.1),
              (422.0, 0, 0.5)]
    return dict(phases=phases, yos=1, abort=0, abort_t=None, waypoints=[arrival_t],
                arrivals=[dict(t=arrival_t, dive_t=dive_t, start=start)], dr=[(463.0, 21.0)], end_t=end_t,
                max_depth=21.6, navigation=True)


def verdict(sil, hil):
    table = hil_flight.Table()
    hil_flight.compare(sil, hil, hil_flight.CASES["waypoint"], table, 20.0, source)
    return [f for f in table.failures if f.startswith("waypoint")]


SIL = flight(22.0, at(-2.4, -2.0), 395.0)
# The proof's failure: a dive a second later from the next epoch's fix.
proof = flight(23.0, at(1.2, 1.7), 383.0)
check(verdict(SIL, proof) == [], "the next epoch's fix (3.6 m east), arrival 383 s against 395 s: passes")
check(abs(383.0 - 395.0) > hil_flight.time_tolerance(395.0), "  (the times alone: 12 s > %.1f s)" %
      hil_flight.time_tolerance(395.0))
# The same fix as SIL, the same arrival: passes (no correction to make).
check(verdict(SIL, flight(22.0, at(-2.4, -2.0), 392.0)) == [], "SIL's fix, arrival 392 s: passes")
# A wrong waypoint: SIL's fix, but arrived 10 m sooner (30 s at 0.33 m/s).
check(verdict(SIL, flight(22.0, at(-2.4, -2.0), 365.0)) != [], "SIL's fix, arrival 365 s (a waypoint 10 m nearer): "
      "fails")
check(verdict(SIL, flight(22.0, at(-2.4, -2.0), 407.0)) != [], "SIL's fix, arrival 407 s: fails")
# A fix 3.6 m east explains 11 s earlier, not 11 s later.
check(verdict(SIL, flight(23.0, at(1.2, 1.7), 407.0)) != [], "the next epoch's fix 3.6 m east, arrival 407 s: fails")
# A start unknown (no DR position in the dive row): the times as they are.
check(verdict(SIL, flight(23.0, None, 383.0)) != [], "no start fix in the HIL log, 383 s: compared as it is, fails")

with tempfile.TemporaryDirectory() as tmp:
    bad_input.check_refused(check, start_fix.read_goto, tmp, (
            ("no_radius.ma", "<start:waypoints>\n724.7 5418.9\n<end:waypoints>\n", "list_when_wpt_dist"),
            ("bad_line.ma", "b_arg: list_when_wpt_dist(m) 30\n<start:waypoints>\n724.7\n<end:waypoints>\n",
             ":3: waypoint"),
            ("bad_lat.ma", "b_arg: list_when_wpt_dist(m) 30\n<start:waypoints>\n724.7 nan\n<end:waypoints>\n",
             ":3: waypoint lat nan")))

print("PASS" if not failures else "FAILED: %d" % len(failures))
sys.exit(1 if failures else 0)
