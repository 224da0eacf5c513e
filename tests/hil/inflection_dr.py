#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""What the compass's cadence does to the waypoint flight, measured on
flights kept by hil_flight.py --keep:

- at each inflection (dive to climb and climb to dive), the dead reckoning
  stops while the pitch is under its 10 deg or disagrees with the depth rate:
  the rows it stops for, in SIL and in HIL. A firmware that sees the pitch
  late keeps counting travel a row longer as the pitch falls ("extra DR
  rows": SIL's stopped rows minus HIL's, when positive);
- the waypoint arrival against the one HIL's own dive predicts (start_fix.py):
  HIL minus expected, s;
- the compass's lag: how far behind the plant's own pitch (plant/truth.csv,
  1 s) the firmware's m_pitch is through the inflections, after the two
  clocks are aligned on the depth (read fresh from the plant at each cycle).

  inflection_dr.py SOURCE_DIR KEPT_DIR...   (each KEPT_DIR: sil.csv, plant/logs/flight-*.csv)
Prints one line per flight and the totals."""
import csv
import glob
import math
import os
import statistics
import sys

source = os.path.abspath(sys.argv[1])
sys.path.insert(0, os.path.join(source, "tests", "hil"))
import hil_flight  # noqa: E402
import start_fix  # noqa: E402

STOP_SEARCH_S = 30.0  # the stop is looked for this far either side of the phase change


def stopped_rows(rows, t_change):
    """Rows around a phase change at t_change in which the DR position (m_lat,
    m_lon) did not move: the run of such rows nearest the change, within
    STOP_SEARCH_S."""
    near = [r for r in rows if abs(r["t"] - t_change) <= STOP_SEARCH_S and r.get("m_lat") is not None]
    runs, run = [], []
    for previous, row in zip(near, near[1:]):
        if (row["m_lat"], row["m_lon"]) == (previous["m_lat"], previous["m_lon"]):
            run.append(row)
        elif run:
            runs.append(run)
            run = []
    if run:
        runs.append(run)
    if not runs:
        return 0
    nearest = min(runs, key=lambda r: min(abs(x["t"] - t_change) for x in r))
    return len(nearest)


def truth(directory):
    """The plant's truth rows (time_s after launch, depth_m, pitch_deg), or None."""
    path = os.path.join(directory, "plant", "truth.csv")
    if not os.path.exists(path):
        return None
    with open(path) as f:
        return [dict((k, float(v)) for k, v in row.items()) for row in csv.DictReader(f)]


def at(rows, key, t):
    """rows[key] linearly at time t (rows at 1 s from 0), None outside."""
    i = int(math.floor(t))
    if i < 0 or i + 1 >= len(rows):
        return None
    f = t - rows[i]["time_s"]
    return rows[i][key] + f * (rows[i + 1][key] - rows[i][key])


def best(candidates, cost):
    return min(candidates, key=cost)


def compass_lag(hil_rows, truth_rows, changes):
    """(clock offset, pitch lag) in s: the plant's time at a row is t + offset
    (least squares on the depth below 1 m); the firmware's pitch is the
    plant's at t + offset - lag (least squares within 15 s of the changes)."""
    deep = [r for r in hil_rows if r["m_depth"] is not None and r["m_depth"] > 1.0]

    def depth_cost(o):
        return sum((r["m_depth"] - v) ** 2 for r in deep if (v := at(truth_rows, "depth_m", r["t"] + o)) is not None)

    offset = best([k / 100.0 for k in range(-300, 301)], depth_cost)
    turning = [r for r in hil_rows if any(abs(r["t"] - t) <= 15.0 for t in changes) and r["m_pitch"] is not None]

    def pitch_cost(lag):
        return sum((math.degrees(r["m_pitch"]) - v) ** 2 for r in turning
                   if (v := at(truth_rows, "pitch_deg", r["t"] + offset - lag)) is not None)

    return offset, best([k / 100.0 for k in range(-100, 201)], pitch_cost)


def inflections(e):
    """Times of the dive-to-climb and climb-to-dive changes."""
    return [(t, p) for t, p, _ in e["phases"] if p in (1, 2)][1:]


def flight(directory):
    logs = glob.glob(os.path.join(directory, "plant", "logs", "flight-*.csv"))
    if len(logs) != 1 or not os.path.exists(os.path.join(directory, "sil.csv")):
        raise SystemExit("%s: want sil.csv and one plant/logs/flight-*.csv" % directory)
    sil_rows, hil_rows = hil_flight.read_log(os.path.join(directory, "sil.csv")), hil_flight.read_log(logs[0])
    sil, hil = hil_flight.events(sil_rows), hil_flight.events(hil_rows)
    pairs = []
    for (ts, ps), (th, ph) in zip(inflections(sil), inflections(hil)):
        if ps == ph:
            pairs.append((stopped_rows(sil_rows, ts), stopped_rows(hil_rows, th)))
    lag = None
    truth_rows = truth(directory)
    if truth_rows:
        lag = compass_lag(hil_rows, truth_rows, [t for t, _ in inflections(hil)])[1]
    offset = None
    goto = start_fix.read_goto(os.path.join(source, hil_flight.CASES["waypoint"]["goto"]))
    if sil["arrivals"] and hil["arrivals"]:
        expected = start_fix.expected_arrival(sil["arrivals"][0], hil["arrivals"][0], goto[0][0], goto[1])
        if expected is not None:
            offset = hil["arrivals"][0]["t"] - expected["t"]
    return pairs, offset, lag


def main():
    all_pairs, offsets, lags = [], [], []
    for directory in sys.argv[2:]:
        pairs, offset, lag = flight(directory)
        all_pairs += pairs
        if offset is not None:
            offsets.append(offset)
        if lag is not None:
            lags.append(lag)
        print("%s: stopped rows SIL/HIL at each inflection %s; HIL - expected arrival %s; compass lag %s" %
              (directory, " ".join("%d/%d" % p for p in pairs), "%.1f s" % offset if offset is not None else "none",
               "%.2f s" % lag if lag is not None else "no truth"))
    extra = [s - h for s, h in all_pairs]
    print("inflections: %d, with extra DR rows in HIL (SIL stopped longer): %d; rows SIL - HIL: %s" %
          (len(extra), sum(1 for x in extra if x > 0), " ".join("%+d" % x for x in extra)))
    if offsets:
        print("HIL - expected arrival, s: %s (median %.1f)" % (" ".join("%.1f" % o for o in offsets),
                                                               statistics.median(offsets)))
    if lags:
        print("compass lag behind the plant's pitch, s: %s (median %.2f)" % (" ".join("%.2f" % x for x in lags),
                                                                            statistics.median(lags)))


if __name__ == "__main__":
    main()
