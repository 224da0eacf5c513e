#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""classify_offset_misses.py on hand-made draws (no binary): one draw per kind of miss, one whose stated other side
is off too, one sized, one not identifiable; each label, partner and count worked out by hand."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import classify_offset_misses as c  # noqa: E402


def draw(seed, truth, findings, forced, ci, identifiable=True, case='buoyancy_offset'):
    """A details entry as diagnose_truth_coverage.py --identifiability writes it (findings: effect -> value)."""
    return {'ok': True, 'case': case, 'seed': seed, 'variant': 'deep', 'truth': truth,
            'findings': [[e, v, None, None, False] for e, v in findings.items()],
            'identifiability': {'buoyancy_offset': {'value': forced, 'ci95': list(ci), 'identifiable': identifiable}}}


OFFSET = 'buoyancy_offset'
CASES = [
    # (draw, the offset's reading on a stated other side, expected cause, partners, forced fit within)
    (draw(1, {OFFSET: 40.0}, {'water_density': 1.0, OFFSET: 41.0}, 40.5, (35, 46)), None, None, '', None),
    (draw(2, {OFFSET: 40.0}, {OFFSET: 10.0}, 11.0, (-20, 40), identifiable=False), None, None, '', None),
    (draw(3, {OFFSET: 40.0, 'hull_compressibility': 2e-10}, {OFFSET: 50.0}, 41.0, (35, 47)), None, c.ABSORBED,
     'hull_compressibility', True),
    (draw(4, {OFFSET: 40.0, 'vertical_water_velocity': 0.01}, {'vertical_water_velocity': 0.02}, 30.0, (20, 40)),
     None, c.IN_ITS_PLACE, 'vertical_water_velocity', False),
    (draw(5, {OFFSET: 40.0, 'pitch_trim_offset': 0.1}, {'pitch_trim_offset': 0.1}, 39.0, (30, 48)), None,
     c.NOTHING_IN_ITS_PLACE, '', True),
    (draw(6, {OFFSET: 40.0}, {OFFSET: 30.0, 'thermal_expansion': 5e-5}, 41.0, (35, 47)), None, c.NAMED_BESIDE,
     'thermal_expansion', True),
    (draw(7, {OFFSET: 40.0}, {OFFSET: 30.0}, 30.0, (20, 40)), None, c.RIGHT_SET_WITHIN_INTERVAL, '', False),
    (draw(8, {OFFSET: 40.0}, {OFFSET: 30.0}, 30.0, (25, 35)), None, c.RIGHT_SET_BEYOND_INTERVAL, '', False),
    (draw(9, {OFFSET: 40.0, 'vertical_water_velocity': 0.01}, {'vertical_water_velocity': 0.02}, 30.0, (20, 40)),
     38.0, c.AMBIGUOUS_OTHER_SIDE, '', False),
    # the stated other side off too: the miss is the partner's
    (draw(10, {OFFSET: 40.0, 'vertical_water_velocity': 0.01}, {'vertical_water_velocity': 0.02}, 30.0, (20, 40)),
     20.0, c.IN_ITS_PLACE, 'vertical_water_velocity', False),
]


def main():
    failures = []
    sides = {d['seed']: side for d, side, *_ in CASES}
    for d, side, cause, partners, forced in CASES:
        if cause is None:
            if c.judged_miss(d):
                failures.append('seed %d: judged a miss' % d['seed'])
            continue
        got = c.classify(d, side)
        if got != (cause, partners.split(',') if partners else [], forced):
            failures.append('seed %d: %s, expected %s' % (d['seed'], got, (cause, partners, forced)))
    lines, counts = c.tabulate([d for d, *_ in CASES], lambda d: sides[d['seed']])
    print('\n'.join(lines))
    if lines[-len(counts) - 1] != 'identifiable 9, within 15 % 1, missed 8':
        failures.append('totals: %s' % lines[-len(counts) - 1])
    if counts[(c.IN_ITS_PLACE, 'vertical_water_velocity')] != [2, 0]:
        failures.append('in its place: %s' % counts[(c.IN_ITS_PLACE, 'vertical_water_velocity')])
    if counts[(c.ABSORBED, 'hull_compressibility')] != [1, 1]:
        failures.append('absorbed: %s' % counts[(c.ABSORBED, 'hull_compressibility')])
    # The other side as the diagnosis states it: in its place (a swap) or beside it (vamb's statement).
    swap = {'effect': 'vertical_water_velocity', 'alternative': OFFSET, 'reading': 'in its place',
            'alternative_value': 38.0}
    beside = {'effect': OFFSET, 'alternative': 'vertical_water_velocity', 'reading': 'beside it', 'value_beside': 36.0,
              'alternative_value': 0.008}
    other = {'effect': 'drag_change', 'alternative': 'lift_change', 'reading': 'in its place',
             'alternative_value': 0.1}
    for report, expected in (({'ambiguous': [swap]}, 38.0), ({'ambiguous': [other, beside]}, 36.0),
                             ({'ambiguous': [other]}, None), ({}, None)):
        if c.other_side_in(report) != expected:
            failures.append('other side of %s: %s, expected %s' % (report, c.other_side_in(report), expected))
    if failures:
        print('FAIL\n' + '\n'.join(failures))
        return 1
    print('PASS the offset\'s misses classified')
    return 0


if __name__ == '__main__':
    sys.exit(main())
