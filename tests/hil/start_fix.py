# SPDX-License-Identifier: Apache-2.0
"""Where a waypoint arrival should fall in HIL given the fix its dive started
from (docs/hil.md, "The launch fix: which GPS epoch the dive starts from").

The firmware dead-reckons each dive from the last GPS fix before it, and
reaches a waypoint when the DR position comes within the goto's
list_when_wpt_dist. glider-plant sends a fix at each whole second of its own
clock; the firmware reads at each whole second of its loop clock; the two
clocks are offset by the plant's launch (the step after the firmware's
first actuator command), so which epoch's fix the firmware dives from -
SIL's or the next, with independent 3 m noise per axis - is decided by a
race of a few wall milliseconds. The distance left to the waypoint's circle
then differs by the two fixes' difference along the track, and the arrival
time by that distance over the approach speed: up to +-15 s for 3 m noise.
Both quantities are measured, in the two logs: the start fix (the DR's
position in the row where the dive begins) and SIL's approach speed.
"""
import math
import re

EARTH_M_PER_DEG = 60.0 * 1852.0  # a nautical mile a minute of latitude


def degrees(ddmm):
    """Slocum's ddmm.mmmm as decimal degrees."""
    d = int(abs(ddmm) / 100)
    return math.copysign(d + (abs(ddmm) - 100 * d) / 60.0, ddmm)


def distance_m(a, b):
    """Flat-earth distance between two (lat, lon) ddmm.mmmm points (a few hundred metres apart)."""
    lat_a, lat_b = degrees(a[0]), degrees(b[0])
    east = (degrees(b[1]) - degrees(a[1])) * EARTH_M_PER_DEG * math.cos(math.radians(0.5 * (lat_a + lat_b)))
    return math.hypot(east, (lat_b - lat_a) * EARTH_M_PER_DEG)


def read_goto(path):
    """The goto_list file's waypoints [(lat, lon) ddmm.mmmm] and its arrival radius (list_when_wpt_dist, m)."""
    with open(path) as f:
        text = f.read()
    m = re.search(r"list_when_wpt_dist\(m\)\s+([0-9.eE+-]+)", text)
    block = re.search(r"<start:waypoints>(.*?)<end:waypoints>", text, re.S)
    if not m or not block:
        raise ValueError("%s: no list_when_wpt_dist(m) or <start:waypoints> block" % path)
    radius = float(m.group(1))
    waypoints = []
    first_line = text.count("\n", 0, block.start(1)) + 1  # the file's line of the block's first
    for n, line in enumerate(block.group(1).splitlines(), start=first_line):
        fields = line.split("#")[0].split()
        if not fields:
            continue
        if len(fields) != 2:
            raise ValueError("%s:%d: waypoint '%s' is not 'lon lat'" % (path, n, line.strip()))
        lon, lat = float(fields[0]), float(fields[1])
        if not (abs(lat) <= 9000.0 and abs(lon) <= 18000.0):
            raise ValueError("%s:%d: waypoint lat %g / lon %g outside +-9000 / +-18000 ddmm" %
                             (path, n, lat, lon))
        waypoints.append((lat, lon))
    if not waypoints or not radius > 0.0:
        raise ValueError("%s: %d waypoints, radius %g m (want >= 1 and > 0)" % (path, len(waypoints), radius))
    return waypoints, radius


def to_circle_m(start, waypoint, radius):
    """Distance from the dive's start fix to the waypoint's arrival circle."""
    return max(0.0, distance_m(start, waypoint) - radius)


def expected_arrival(sil, hil, waypoint, radius):
    """HIL's arrival time predicted from its own dive (start time and fix) and
    SIL's approach speed: t_dive_hil + d_hil / (d_sil / (t_sil - t_dive_sil)).
    sil, hil: dicts with t (arrival), dive_t and start (lat, lon) of the dive
    that reached the waypoint. None when a start is unknown or SIL had no
    approach to measure a speed on (then the times are compared as they are)."""
    if sil["start"] is None or hil["start"] is None:
        return None
    d_sil = to_circle_m(sil["start"], waypoint, radius)
    d_hil = to_circle_m(hil["start"], waypoint, radius)
    approach_s = sil["t"] - sil["dive_t"]
    if not approach_s > 0.0 or not d_sil > 0.0:
        return None
    return dict(t=hil["dive_t"] + d_hil * approach_s / d_sil, d_sil=d_sil, d_hil=d_hil, speed=d_sil / approach_s)
