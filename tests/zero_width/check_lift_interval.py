#!/usr/bin/env python3
"""A forced fit whose Jacobian interval collapsed (issue 26 item 4).

glider-truth --variant shallow --seed 1002 --yos 6 --effect lift_change=0.8,
then glider-diagnose --fit lift_change --plane vertical: before the profile
check the fit read lift_change 2.7542 [2.75417, 2.75421] - a 95 % interval of
1.5e-5 of its value, the truth (0.8) far outside. The seed is fixed on
purpose: it is the log where the collapse was found (a paired sweep of seeds
1000-1030, base vs checked binary); the unit tests (diagnose.zero_width.
Intervals) draw fresh seeds. Passes when the interval is at least 1 % of the
value wide (the profile's is ~2x the value) and holds the fitted value.

Usage: check_lift_interval.py GLIDER_TRUTH GLIDER_DIAGNOSE VEHICLE WORKDIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import diagnose_log, fly  # noqa: E402


def main(truth, diagnose, vehicle, workdir):
    os.makedirs(workdir, exist_ok=True)
    log = os.path.join(workdir, 'lift_change_1002.csv')
    fly(truth, 'shallow', 1002, {'lift_change': 0.8}, log)
    found = [f for f in diagnose_log(diagnose, log, vehicle, ['--fit', 'lift_change'])['findings']
             if f['effect'] == 'lift_change']
    if not found:
        print('FAIL: no lift_change finding from a forced fit')
        return 1
    value, (low, high) = found[0]['value'], found[0]['ci95']
    width = (high - low) / abs(value)
    print(f'lift_change {value:.6g} [{low:.6g}, {high:.6g}]: width {width:.3g} of the value (truth 0.8)')
    if not (low <= value <= high):
        print('FAIL: the interval does not hold its value')
        return 1
    if not width >= 0.01:
        print('FAIL: a collapsed interval (narrower than 1 % of the value)')
        return 1
    print('PASS no zero-width interval')
    return 0


if __name__ == '__main__':
    if len(sys.argv) != 5:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
