#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""The overload verdict (overload_verdict.py) on lateness records built here:
- a paused plant's record (an answer 480 ms late, three requests in one
  read) at an actuator-fault abort: overloaded;
- the same record at an abort a minute later, a step that woke late with no
  late answer, an answer 99.9 ms late (under the firmware's 100 ms
  response timeout), a depth-sensor abort: judged (not overloaded);
- the window's edges, and its width with the time scale;
- random records (fresh seed, printed): steps alone never excuse an abort;
  late answers outside the window do not; one inside does;
- hil_flight.conclude's exits on a plant directory built here (77 for an
  overloaded failure, 1 for a prompt one, the verdict cases' own passes);
- a bad record or board names the file, line, key and value.
  check_overload_verdict.py SOURCE_DIR [--seed N]"""
import argparse
import io
import os
import random
import sys
import tempfile
from contextlib import redirect_stdout

parser = argparse.ArgumentParser()
parser.add_argument("source")
parser.add_argument("--seed", type=int, help="replay a run (default: a fresh seed, printed)")
a = parser.parse_args()
sys.path.insert(0, os.path.join(os.path.abspath(a.source), "tests", "hil"))
import bad_input  # noqa: E402
import hil_flight  # noqa: E402
import overload_verdict as ov  # noqa: E402

SEED = a.seed if a.seed is not None else random.SystemRandom().randrange(2**31)
print("seed %d (replay: --seed %d)" % (SEED, SEED))
rng = random.Random(SEED)
failures = []
TIMEOUT_MS, BUDGET_MS, SCALE = 100.0, 400.0, 20.0
ACTUATOR, DEPTH = 5, 3


def check(ok, what):
    print("%s: %s" % ("ok" if ok else "FAIL", what))
    if not ok:
        failures.append(what)


def step(t, late):
    return dict(kind="step", t_s=t, late_ms=late, requests=0)


def answer(t, late, requests=1):
    return dict(kind="answer", t_s=t, late_ms=late, requests=requests)


def verdict(records, abort_t=61.0, cause=ACTUATOR, scale=SCALE):
    return ov.judge(cause, abort_t, records, TIMEOUT_MS, BUDGET_MS, scale)[0]


PAUSED = [step(59.9, 500.4), answer(59.9, 480.2, 3), step(60.0, 21.0)]
check(verdict(PAUSED), "a paused plant (answer 480 ms late, 3 requests) at an actuator abort at 61 s: overloaded")
evidence = ov.judge(ACTUATOR, 61.0, PAUSED, TIMEOUT_MS, BUDGET_MS, SCALE)[1]
check(any("480.2 ms" in line for line in evidence) and any("500.4 ms" in line for line in evidence),
      "  the evidence names the late answer and the late step")
check(not verdict(PAUSED, abort_t=125.0), "the same record, an abort at 125 s: judged (a prompt plant then)")
check(not verdict([step(60.5, 900.0)]), "a step 900 ms late but no late answer: judged (no request was waiting)")
check(not verdict([answer(60.5, 99.9)]), "an answer 99.9 ms late (timeout 100 ms): judged")
check(verdict([answer(60.5, 100.0)]), "an answer 100.0 ms late: overloaded")
check(verdict([answer(60.5, 3.0, 2)]), "two requests in one read, the newest 3 ms late: overloaded")
check(verdict([answer(60.5, None, 2)]), "two requests in one read, untimed: overloaded")
check(not verdict([answer(60.5, None, 1)]), "one untimed request: judged")
check(not verdict(PAUSED, cause=DEPTH), "a depth-sensor abort with the paused record: judged (not the actuators)")
check(not verdict(PAUSED, abort_t=None), "no abort: judged")
# The window: the budget 400 ms x 20 + 2 s = 10 s before the abort's row, 1 s after.
check(verdict([answer(51.0, 300.0)]) and not verdict([answer(50.9, 300.0)]), "window's start: 61 - 10 s")
check(verdict([answer(62.0, 300.0)]) and not verdict([answer(62.1, 300.0)]), "window's end: 61 + 1 s")
check(not verdict([answer(54.0, 300.0)], scale=10.0) and verdict([answer(55.0, 300.0)], scale=10.0),
      "at time scale 10 the window starts 6 s before")

# Random records: invariants of the rule, not the rule again.
for _ in range(200):
    abort_t = rng.uniform(20.0, 400.0)
    lo, hi = abort_t - (BUDGET_MS / 1000.0 * SCALE + 2.0), abort_t + 1.0
    steps = [step(rng.uniform(0.0, 450.0), rng.uniform(20.0, 2000.0)) for _ in range(rng.randrange(0, 30))]
    outside = []
    for _ in range(rng.randrange(0, 10)):
        t = rng.choice([rng.uniform(0.0, lo - 0.01) if lo > 0.01 else hi + 1.0, rng.uniform(hi + 0.01, 460.0)])
        outside.append(answer(t, rng.uniform(100.0, 2000.0), rng.randrange(1, 4)))
    prompt = [answer(rng.uniform(lo, hi), rng.uniform(0.0, 99.8), 1) for _ in range(rng.randrange(0, 10))]
    base = steps + outside + prompt
    if verdict(base, abort_t):
        check(False, "seed %d: steps, prompt answers and late answers outside the window excused an abort at "
                     "%.1f s" % (SEED, abort_t))
        break
    inside = answer(rng.uniform(lo, hi), rng.uniform(100.0, 2000.0), rng.randrange(1, 4))
    if not verdict(base + [inside], abort_t) or verdict(base + [inside], abort_t, cause=rng.choice([1, 3, 4, 9])):
        check(False, "seed %d: a late answer at %.2f s in the window of an abort at %.1f s" %
              (SEED, inside["t_s"], abort_t))
        break
else:
    check(True, "200 random records: only a late answer in the window of an actuator abort excuses it")


def conclude_exit(case, problems, records, abort=ACTUATOR, abort_t=61.0):
    """hil_flight.conclude on a plant directory built here: its exit code (None: it returned), its output."""
    with tempfile.TemporaryDirectory() as plant:
        with open(os.path.join(plant, "actuators.toml"), "w") as f:
            f.write("[bus]\nresponse_timeout_ms = 100\ncycle_budget_ms = 400\n")
        with open(os.path.join(plant, "lateness.csv"), "w") as f:
            f.write("kind,t_s,late_ms,requests\n")
            for r in records:
                f.write("%s,%.2f,%s,%d\n" % (r["kind"], r["t_s"], "" if r["late_ms"] is None else r["late_ms"],
                                             r["requests"]))
        out = io.StringIO()
        code = None
        with redirect_stdout(out):
            try:
                hil_flight.conclude("x", case, problems, dict(abort=abort, abort_t=abort_t), plant, SCALE)
            except SystemExit as e:
                code = e.code
        return code, out.getvalue()


WAYPOINT = hil_flight.CASES["waypoint"]
code, out = conclude_exit(WAYPOINT, ["glider-firmware exit status 3"], PAUSED)
check(code == 77 and "overloaded, not judged" in out and "480.2 ms" in out,
      "conclude: a failed flight, actuator abort, paused plant: exit 77 with the evidence (%s)" % code)
code, out = conclude_exit(WAYPOINT, ["glider-firmware exit status 3"], PAUSED, abort_t=125.0)
check(code == 1 and "FAIL hil x" in out, "conclude: the same, the abort a minute later: exit 1 (%s)" % code)
check(conclude_exit(WAYPOINT, [], PAUSED)[0] is None, "conclude: a passing flight returns (the record unread)")
check(conclude_exit(hil_flight.CASES["plant_paused"], ["abort cause"], PAUSED)[0] == 0,
      "conclude: case plant_paused passes on the overloaded verdict")
check(conclude_exit(hil_flight.CASES["plant_paused"], ["abort cause"], [])[0] == 1,
      "conclude: case plant_paused fails without the plant's evidence")
check(conclude_exit(hil_flight.CASES["actuator_fault_prompt"], ["outside tolerance"], [])[0] == 0,
      "conclude: case actuator_fault_prompt passes on a prompt plant's failure")
check(conclude_exit(hil_flight.CASES["actuator_fault_prompt"], [], [])[0] == 1,
      "conclude: case actuator_fault_prompt fails when the flight passed")

with tempfile.TemporaryDirectory() as tmp:
    bad_input.check_refused(check, ov.read_record, tmp, (
            ("header.csv", "kind,t,late,n\n", ":1: header"),
            ("nan.csv", "kind,t_s,late_ms,requests\nstep,nan,3.0,0\n", ":2: t_s nan outside"),
            ("negative.csv", "kind,t_s,late_ms,requests\nanswer,1.0,-4,1\n", ":2: late_ms -4 outside"),
            ("word.csv", "kind,t_s,late_ms,requests\nanswer,1.0,late,1\n", ":2: late_ms 'late' is not a number"),
            ("kind.csv", "kind,t_s,late_ms,requests\nstall,1.0,3.0,0\n", ":2: kind 'stall'"),
            ("fields.csv", "kind,t_s,late_ms,requests\nstep,1.0,3.0\n", ":2: 3 fields"),
            ("fraction.csv", "kind,t_s,late_ms,requests\nanswer,1.0,3.0,1.5\n", ":2: requests 1.5"),
            ("step_untimed.csv", "kind,t_s,late_ms,requests\nstep,1.0,,0\n", ":2: late_ms '' is not a number")))
    with open(os.path.join(tmp, "actuators.toml"), "w") as f:
        f.write("[bus]\nresponse_timeout_ms = 100\n")
    try:
        ov.read_bus(tmp)
        check(False, "a board without cycle_budget_ms refused")
    except ValueError as e:
        check("actuators.toml" in str(e) and "cycle_budget_ms" in str(e), "a board without cycle_budget_ms: %s" % e)

print("PASS" if not failures else "FAILED: %d (seed %d)" % (len(failures), SEED))
sys.exit(1 if failures else 0)
