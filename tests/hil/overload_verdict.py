# SPDX-License-Identifier: Apache-2.0
"""Whether a HIL flight's actuator-fault abort was the plant's lateness, not
the firmware's.

The firmware's Modbus link gives an attempt up after the board's
response_timeout_ms (100 ms) and a transaction after its retries or the
cycle's budget (cycle_budget_ms, 400 ms), and one failed transaction is an
actuator fault, so an abort. On a heavily overloaded machine the plant
itself can be unscheduled that long: the firmware then aborts on a plant
that answered late, which says nothing about the firmware. The plant
records its own lateness (DIR/lateness.csv, tools/hardware/plant/
lateness_record.hpp): steps that woke late and Modbus reads whose answer
was late or that held several requests.

The rule: an actuator-fault abort at t_a (simulated seconds after the
firmware's first row) is "overloaded, not judged" when, in the plant's
record between t_a - (cycle budget x time scale + 2 s) and t_a + 1 s
(the failing cycle blocks up to its budget before its row is stamped; the
plant's clock starts at the firmware's first actuator command, within its
first cycle), a Modbus answer left response_timeout_ms or more after its
request arrived, or a read held two or more requests (the firmware sends a
request only when the previous one was answered or given up: the earlier
ones had timed out). That is the actuators' own lateness, the cause of the
fault. A step that woke late is shown beside it but is not enough alone: a
plant can stall while no request waits.
"""
import math
import os
import tomllib

WINDOW_MARGIN_BEFORE_S = 2.0
WINDOW_AFTER_S = 1.0
ACTUATOR_FAULT = 5  # hil_flight.ABORT_NAMES


def read_record(path):
    """The plant's lateness rows as dicts: kind ("step"/"answer"), t_s,
    late_ms (None: untimed answer), requests. ValueError naming the file,
    line, key and value on anything else (NaN never passes)."""
    rows = []
    with open(path) as f:
        header = f.readline().strip()
        if header != "kind,t_s,late_ms,requests":
            raise ValueError("%s:1: header '%s', expected 'kind,t_s,late_ms,requests'" % (path, header))
        for n, line in enumerate(f, start=2):
            fields = line.rstrip("\n").split(",")
            if len(fields) != 4:
                raise ValueError("%s:%d: %d fields, expected 4: '%s'" % (path, n, len(fields), line.strip()))
            kind, t_text, late_text, requests_text = fields
            if kind not in ("step", "answer"):
                raise ValueError("%s:%d: kind '%s', expected step or answer" % (path, n, kind))

            def number(key, text, allow_empty=False):
                if text == "" and allow_empty:
                    return None
                try:
                    value = float(text)
                except ValueError:
                    raise ValueError("%s:%d: %s '%s' is not a number" % (path, n, key, text)) from None
                if not math.isfinite(value) or value < 0.0:
                    raise ValueError("%s:%d: %s %s outside [0, inf)" % (path, n, key, text))
                return value

            requests = number("requests", requests_text)
            if requests != int(requests):
                raise ValueError("%s:%d: requests %s is not a whole number" % (path, n, requests_text))
            rows.append(dict(kind=kind, t_s=number("t_s", t_text),
                             late_ms=number("late_ms", late_text, allow_empty=kind == "answer"),
                             requests=int(requests)))
    return rows


def read_bus(plant_dir):
    """The firmware's Modbus timing from the board the plant wrote (DIR/actuators.toml): response_timeout_ms,
    cycle_budget_ms."""
    path = os.path.join(plant_dir, "actuators.toml")
    with open(path, "rb") as f:
        bus = tomllib.load(f).get("bus", {})
    values = []
    for key in ("response_timeout_ms", "cycle_budget_ms"):
        value = bus.get(key)
        if not isinstance(value, (int, float)) or not value > 0:
            raise ValueError("%s: bus.%s = %r, expected a number > 0" % (path, key, value))
        values.append(float(value))
    return tuple(values)


def judge(abort_cause, abort_t, records, response_timeout_ms, cycle_budget_ms, scale):
    """(overloaded, evidence lines). overloaded only for an actuator-fault
    abort with a late answer of the plant in the window (module doc)."""
    if abort_cause != ACTUATOR_FAULT or abort_t is None:
        return False, []
    before = cycle_budget_ms / 1000.0 * scale + WINDOW_MARGIN_BEFORE_S
    lo, hi = abort_t - before, abort_t + WINDOW_AFTER_S
    window = [r for r in records if lo <= r["t_s"] <= hi]
    late = [r for r in window if r["kind"] == "answer" and
            ((r["late_ms"] is not None and r["late_ms"] >= response_timeout_ms) or r["requests"] >= 2)]
    steps = [r for r in window if r["kind"] == "step"]
    answers = [r for r in window if r["kind"] == "answer"]
    lines = ["actuator fault abort at %.1f s; the plant's record from %.1f to %.1f s (the cycle budget %.0f ms x "
             "time scale %g + %.0f s before, %.0f s after):" % (abort_t, lo, hi, cycle_budget_ms, scale,
                                                                 WINDOW_MARGIN_BEFORE_S, WINDOW_AFTER_S)]
    for r in late:
        timed = "%.1f ms after its request arrived" % r["late_ms"] if r["late_ms"] is not None else "untimed"
        lines.append("  Modbus answer at %.2f s: %s, %d request(s) in one read (the firmware's response timeout "
                     "%.0f ms)" % (r["t_s"], timed, r["requests"], response_timeout_ms))
    if not late:
        worst = max((r["late_ms"] or 0.0 for r in answers), default=None)
        lines.append("  no Modbus answer >= %.0f ms late or with several requests (late answers recorded: %d, "
                     "worst %s)" % (response_timeout_ms, len(answers),
                                    "%.1f ms" % worst if worst is not None else "none"))
    if steps:
        worst = max(steps, key=lambda r: r["late_ms"])
        lines.append("  plant steps woken late: %d, worst %.1f ms at %.2f s" % (len(steps), worst["late_ms"],
                                                                              worst["t_s"]))
    else:
        lines.append("  plant steps woken late: none recorded")
    return bool(late), lines
