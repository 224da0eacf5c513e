#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A stronger fin is named as a fin, not as a roll offset; a roll offset is
named where the rate error's biased fin had hidden it.

Two fixed draws of the independent truth (tools/science/truth), diagnosed as
a black box (`glider-diagnose --plane heading --json`):

- shallow variant, fin effectiveness x1.908 alone: the glider flies rolled
  (-10 deg) and its loop holds the fin against the roll's yaw, so to the
  yaw-rate error a stronger fin and a roll offset are one column, and the
  closed loop reads the fin weaker. The code before this rule named a roll
  offset of +0.098 rad [0.075, 0.121] and no fin. The fin must be named,
  its interval holding 1.908, and no roll offset.
- deep variant, roll offset -0.0659 rad alone: the rate error named a fin
  that its measurement on the innovations refuted, and the code before
  named nothing. The roll offset must be named, its interval holding the
  truth, and no fin.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
import truth_draw  # noqa: E402


def fly(truth, source, out, variant, seed, effects, prefix='fin_or_roll'):
    """A truth log of 6 yos with these effects hidden (its truth beside it as .json), and its variant's vehicle
    file in the checkout `source`."""
    log = os.path.join(out, '%s_%d.csv' % (prefix, seed))
    truth_draw.fly(truth, variant, seed, effects, log, truth_json=os.path.join(out, '%s_%d.json' % (prefix, seed)))
    return log, truth_draw.vehicle_file(os.path.join(source, 'boards', 'vehicles'), variant)


def diagnose(truth, program, source, out, variant, seed, effects):
    """The heading plane's findings by effect on fly's log."""
    log, vehicle = fly(truth, source, out, variant, seed, effects)
    return truth_draw.heading_findings(truth_draw.diagnose_log(program, log, vehicle, plane='heading'))


def check(failures, found, effect, truth, absent):
    f = found.get(effect)
    print('%s %.4f hidden: findings %s' % (effect, truth, {
        k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']]) for k, v in found.items()}))
    if f is None:
        failures.append('%s %.4f not named' % (effect, truth))
    elif not f['ci95'][0] <= truth <= f['ci95'][1]:
        failures.append('%s interval %s misses %.4f' % (effect, f['ci95'], truth))
    if absent in found:
        failures.append('%s named beside a hidden %s' % (absent, effect))


VEHICLE_LINK = {'fin_effectiveness', 'roll_offset', 'yaw_time_constant', 'yaw_delay'}


def check_clean(failures, clean):
    """A clean log's vehicle link names nothing."""
    named = sorted(e for e in clean if e in VEHICLE_LINK)
    print('clean: findings %s' % {k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']])
                                  for k, v in clean.items()})
    if named:
        failures.append('a clean log names %s' % ', '.join(named))


def finish(failures, passed):
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS ' + passed)
    return 0


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    fin = 1.90766954
    check(failures, diagnose(truth, program, source, out, 'shallow', 284645423434941016,
                             {'fin_effectiveness': fin}), 'fin_effectiveness', fin, 'roll_offset')
    roll = -0.0658779576
    check(failures, diagnose(truth, program, source, out, 'deep', 5253771433374317794, {'roll_offset': roll}),
          'roll_offset', roll, 'fin_effectiveness')
    return finish(failures, 'fin or roll named as hidden')


if __name__ == '__main__':
    sys.exit(main())
