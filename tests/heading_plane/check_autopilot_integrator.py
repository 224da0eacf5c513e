#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The autopilot's integrator at each glide's start: a state per glide.

Fresh independent-truth logs (tools/science/truth; a fresh seed each run,
printed: `check_autopilot_integrator.py TRUTH DIAGNOSE SOURCE OUT [SEED]`
replays one) whose heading truth is clean, diagnosed as a black box
(`glider-diagnose --plane heading --json`). The truth's autopilot integrates
over its nominal cycle, the replay over each row's interval: in a wind-up the
two integrators part, the replay misses the log's c_fin by a constant for
the rest of the glide and named that as an autopilot delay, deadband or rate
gain on about one clean log in ten (docs/science.md "The autopilot's
integrator at each glide's start"). With the integrator's state profiled out
per glide (unless the replayed integrator's set flies the held-out glides
better closed-loop - the JSON's heading.autopilot_integrator says which
stood):

- the per-glide integrator stands on at least three of the four clean logs;
  where it stands the stated law explains the logged c_fin no worse (the
  autopilot link's nominal held-out RMS at most the replayed integrator's),
  and strictly better on at least two of the four. A bit-equal held-out RMS
  is a tie that judges nothing: the held-out glides' integrators never part
  (no wind-up there), so profiling the state out changes nothing (measured:
  fresh seed 777283143, 40 clean logs: 39 better, 1 tie, none worse; the
  tie of 0.00065 rad on seed 984676907 failed CI stop 39 when a tie counted
  as worse). Without the rule the option does not exist, and a per-glide
  integrator that changed nothing would tie everywhere: this fails;
- at most one of the four clean logs names an autopilot effect (measured
  with the rule: 1 of 36 clean logs, a delay of 2.3 s on a deep draw whose
  stated law still misses c_fin by 0.024 rad within glides - other timing;
  two of four at that rate: about 1 run in 200);
- a hidden autopilot integral far from the stated one (0.045 against 0.02 /s)
  that the replayed integrator names within 15 % of its change is named so
  with the rule too: the integral's build-up within a glide is left to the
  fit. Judged paired over four draws: on its own the integral is named
  within 15 % in about 6 draws of 7 with either integrator (paired, 12 fresh
  draws, seed 1541531057, both variants: per glide 11 named / 10 within,
  replayed 10 / 9; the unpaired check failed 3 runs of 11). A draw the
  replayed rule misses too judges nothing. The per-glide rule loses a draw
  the replayed one names now and then (seed 103717384: the per-glide fit
  under the measured clock took an autopilot gain 0.63 for the integral, the
  nominal clock named 0.0449, and the two clocks' rule names only what both
  name); on shallow draws of fresh seed 550477421 it lost 0 of 40 and won 2.
  It fails on two or more lost draws of four, which a loss rate of one draw
  in 40 reaches about once in 170 runs (6 x 0.025^2), and a per-glide rule
  that lost the integral everywhere fails. (Its interval is not checked here:
  it missed 0.045 by a hair with either integrator on one draw - the heading
  plane's intervals are another rule's.)
"""
import os
import random
import secrets
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from check_fin_or_roll import fly  # noqa: E402
from truth_draw import diagnose_log  # noqa: E402


def diagnose(program, log, vehicle, integrator):
    heading = diagnose_log(program, log, vehicle, ['--autopilot-integrator', integrator], plane='heading',
                           timeout=300)['heading']
    return heading['links']['autopilot'], heading['autopilot_integrator']


def main():
    truth, program, source, out = sys.argv[1:5]
    seed = int(sys.argv[5]) if len(sys.argv) > 5 else secrets.randbits(31)
    print('seed %d (replay: check_autopilot_integrator.py TRUTH DIAGNOSE SOURCE OUT %d)' % (seed, seed))
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    failures, ratios, naming = [], [], []
    replayed_stood = 0
    better = 0
    for k in range(4):
        variant = 'deep' if k % 2 else 'shallow'
        draw = rng.getrandbits(62)
        log, vehicle = fly(truth, source, out, variant, draw, {}, 'integrator')
        per_glide, stood = diagnose(program, log, vehicle, 'per-glide')
        replayed, _ = diagnose(program, log, vehicle, 'replayed')
        a, b = per_glide['baseline']['heldout_rms'], replayed['baseline']['heldout_rms']
        named = [f['effect'] for f in per_glide['findings']]
        print('clean %s draw %d (%s stands): stated law held out %.5f rad per glide, %.5f replayed; named %s '
              '(replayed: %s)' % (variant, draw, stood, a, b, named or 'none',
                                  [f['effect'] for f in replayed['findings']] or 'none'))
        ratios.append(a / b)
        replayed_stood += stood == 'replayed'
        if stood == 'per-glide' and a > b:
            failures.append('draw %d: the per-glide integrator explains c_fin worse (%.5f vs %.5f)' % (draw, a, b))
        if a == b:
            print('  a tie: the held-out glides\' integrators never part; this draw judges nothing')
        better += stood == 'per-glide' and a < b
        if named:
            naming.append('clean draw %d names %s' % (draw, ', '.join(named)))
    print('held-out ratio per glide / replayed: median %.2f' % statistics.median(ratios))
    if len(naming) > 1:
        failures += naming
    if replayed_stood > 1:
        failures.append('the replayed integrator stood on %d of 4 clean logs' % replayed_stood)
    if better < 2:
        failures.append('the per-glide integrator explains c_fin better on %d of 4 clean logs (2 needed)' % better)
    integral = 0.045
    lost = []
    for _ in range(4):
        draw = rng.getrandbits(62)
        log, vehicle = fly(truth, source, out, 'shallow', draw, {'autopilot_integral': integral}, 'integrator')

        def within(mode):
            found = {f['effect']: f for f in diagnose(program, log, vehicle, mode)[0]['findings']}
            print('autopilot_integral %.3f hidden, draw %d, %s: findings %s' % (integral, draw, mode, {
                e: (round(f['value'], 4), [round(x, 4) for x in f['ci95']]) for e, f in found.items()}))
            f = found.get('autopilot_integral')
            return f is not None and abs(f['value'] - integral) <= 0.15 * abs(integral - 0.02), f

        replayed_within, _ = within('replayed')
        per_glide_within, f = within('per-glide')
        if not replayed_within:
            print('  the replayed integrator does not name it within 15 % either: this draw judges nothing')
        elif not per_glide_within:
            print('  lost with the rule')
            lost.append('draw %d %s' % (draw, 'not named' if f is None else 'read %.4f' % f['value']))
    if len(lost) >= 2:
        failures.append('autopilot_integral %.3f within 15 %% replayed, lost with the rule on %d of 4 draws (%s)' %
                        (integral, len(lost), '; '.join(lost)))
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS autopilot integrator per glide')
    return 0


if __name__ == '__main__':
    sys.exit(main())
