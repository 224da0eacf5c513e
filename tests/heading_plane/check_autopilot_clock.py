#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The autopilot link fitted under both clocks its law may integrate over
(docs/science.md, "The autopilot's clock").

Fixed draws of the independent truth (tools/science/truth), diagnosed as a
black box (`glider-diagnose --plane heading --json`), regression cases on
purpose. The truth steps its integrator by its nominal cycle while its
cycles jitter +-5 %; the replay over the measured intervals (hdap2's rule)
then misses by a few hundredths of a radian per wind-up, and:

- yaw time constant 6.40 s (shallow): it named an autopilot delay of 1.84 s
  and a dgain of -8.27; the autopilot link must name nothing.
- autopilot integral 0.0576 (shallow): it named a deadband of 0.01 beside
  it; the integral must be named, its interval holding the truth, and
  nothing else on the autopilot link.
- autopilot gain 2.786 (shallow): its interval [2.788, 2.826] missed; and
  gain 0.676 with a delay of 2.07 s (shallow): [0.639, 0.675] and
  [0.5, 2.0] missed. Each interval must hold its truth.

With both clocks fitted the link keeps what both name, at the middle of
the two readings, its interval spanning both. The same draws diagnosed
with `--autopilot-clock measured` must fail (the rule is what passes).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from check_fin_or_roll import finish, fly  # noqa: E402
from truth_draw import diagnose_log  # noqa: E402

AUTOPILOT_LINK = {'autopilot_gain', 'autopilot_integral', 'autopilot_dgain', 'autopilot_delay', 'autopilot_deadband'}
DRAWS = (('shallow', 3101744281786930969, {'yaw_time_constant': 6.39922825}),
         ('shallow', 1416917262185374968, {'autopilot_integral': 0.0575680164}),
         ('shallow', 5831683570397952070, {'autopilot_gain': 2.78606523}),
         ('shallow', 4844297034159761267, {'autopilot_gain': 0.676491136, 'autopilot_delay': 2.07104485}))


def autopilot_findings(program, log, vehicle, extra):
    document = diagnose_log(program, log, vehicle, extra, plane='heading')
    link = ((document.get('heading') or {}).get('links') or {}).get('autopilot') or {}
    return {f['effect']: f for f in link.get('findings', []) or []}


def judge(found, effects):
    """What is wrong with the autopilot link's findings for these hidden effects."""
    wrong = []
    for effect, value in effects.items():
        if effect not in AUTOPILOT_LINK:
            continue
        f = found.get(effect)
        if f is None:
            wrong.append('%s %.4f not named' % (effect, value))
        elif not f['ci95'][0] <= value <= f['ci95'][1]:
            wrong.append('%s interval [%.4f, %.4f] misses %.4f' % (effect, f['ci95'][0], f['ci95'][1], value))
    extra = sorted(e for e in found if e not in effects)
    if extra:
        wrong.append('also named %s' % ', '.join(extra))
    return wrong


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures, control = [], []
    for variant, seed, effects in DRAWS:
        log, vehicle = fly(truth, source, out, variant, seed, effects, prefix='autopilot_clock')
        found = autopilot_findings(program, log, vehicle, [])
        wrong = judge(found, effects)
        print('%s %d %s: autopilot link %s %s' % (variant, seed, effects, {
            k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']]) for k, v in found.items()}, wrong or 'ok'))
        failures += ['%d: %s' % (seed, w) for w in wrong]
        measured = judge(autopilot_findings(program, log, vehicle, ['--autopilot-clock', 'measured']), effects)
        print('  measured clock only: %s' % (measured or 'ok'))
        control += measured
    if not control:
        failures.append('the measured clock alone passes every draw: the test no longer checks the rule')
    return finish(failures, 'autopilot link under both clocks')


if __name__ == '__main__':
    sys.exit(main())
