#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The CTD's density is flown from the start; a thermal expansion does not stand in for it.

Logs of the independent truth (tools/science/truth), two fixed draws of a
heavy buoyancy offset alone (6 yos; the regression cases, found on fresh
benchmark seeds), diagnosed as a black box (`glider-diagnose --plane
vertical --json`). The code before left the CTD's density to earn its place
by the selection's margins: with the offset still missing, the true
stratification made the nominal fit worse, the density was declined, and a
negative thermal expansion near -2e-4 /K stood in for the density and the
offset together (docs/science.md, "the CTD's density flown from the start"):

- shallow, +67.95 g (draw 8490527760697439514 of benchmark seed 1834244384):
  before, thermal_expansion -2.21e-4 /K and buoyancy_offset -26.5 g.
- deep, +51.84 g (draw 7891877463615551685 of benchmark seed 1964417921):
  before, thermal_expansion -2.03e-4 /K alone.

Each must name the CTD's density and the offset within 15 % with an
interval that holds it, and no thermal expansion.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import findings, fly_and_diagnose, vehicle_file  # noqa: E402

DRAWS = [('shallow', 8490527760697439514, 67.9466049), ('deep', 7891877463615551685, 51.8400814)]


def main():
    truth, program, vehicles, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    for variant, seed, hidden in DRAWS:
        found = findings(fly_and_diagnose(truth, program, vehicle_file(vehicles, variant), out, 'offset',
                                          variant, seed, {'buoyancy_offset': hidden}))
        print('seed %d (%s, %+.2f g hidden): %s' % (seed, variant, hidden, ', '.join(
            '%s %.4g' % (e, f['value']) for e, f in found.items())))
        if 'water_density' not in found:
            failures.append('seed %d: the CTD density not flown' % seed)
        if 'thermal_expansion' in found:
            failures.append('seed %d: a thermal expansion %.3g /K named' % (seed, found['thermal_expansion']['value']))
        offset = found.get('buoyancy_offset')
        if offset is None:
            failures.append('seed %d: the offset not named' % seed)
            continue
        low, high = offset['ci95']
        if not abs(offset['value'] - hidden) <= 0.15 * abs(hidden):
            failures.append('seed %d: offset %.2f g, not within 15 %% of %.2f' % (seed, offset['value'], hidden))
        if not low <= hidden <= high:
            failures.append('seed %d: [%.2f, %.2f] misses %.2f' % (seed, low, high, hidden))
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS the CTD density flown from the start')
    return 0


if __name__ == '__main__':
    sys.exit(main())
