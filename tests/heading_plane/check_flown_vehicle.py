#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The heading plane flies the vertical plane's findings (docs/science.md,
"The heading plane flies the vertical plane's findings").

Two fixed draws of the independent truth, shallow variant, a vertical drag
change hidden and the heading clean, diagnosed as a black box
(`glider-diagnose --plane both --json`). With the vehicle file's drag the
heading plane's glide speed is too fast and the roll's yaw too strong: the
code before named a roll offset of -0.106 rad [-0.159, -0.053] (drag 1.400)
and -0.113 rad [-0.159, -0.067] (drag 1.479). The vertical plane must name
the drag (its interval holding the truth) and the heading plane's vehicle
link must name nothing.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from check_fin_or_roll import VEHICLE_LINK, finish, fly  # noqa: E402
from truth_draw import diagnose_log, findings, heading_findings  # noqa: E402


def both_planes(truth, program, source, out, seed, drag):
    log, vehicle = fly(truth, source, out, 'shallow', seed, {'drag_change': drag}, prefix='flown_vehicle')
    document = diagnose_log(program, log, vehicle, plane='both')
    return findings(document), heading_findings(document)


def check(failures, vertical, heading, drag):
    print('drag_change %.4f hidden: vertical %s, heading %s' % (
        drag, {k: round(v['value'], 4) for k, v in vertical.items()},
        {k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']]) for k, v in heading.items()}))
    f = vertical.get('drag_change')
    if f is None:
        failures.append('drag_change %.4f not named' % drag)
    elif not f['ci95'][0] <= drag <= f['ci95'][1]:
        failures.append('drag_change interval %s misses %.4f' % (f['ci95'], drag))
    named = sorted(e for e in heading if e in VEHICLE_LINK)
    if named:
        failures.append('a clean heading beside a hidden drag %.4f names %s' % (drag, ', '.join(named)))


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    for seed, drag in ((9043862276282734444, 1.40024207), (6909467400517235260, 1.47905034)):
        check(failures, *both_planes(truth, program, source, out, seed, drag), drag)
    return finish(failures, 'heading clean beside a hidden drag')


if __name__ == '__main__':
    sys.exit(main())
