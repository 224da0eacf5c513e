#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Why identifiable draws missed 15 % (benchmarks/identifiability.py --misses), on a hand-made run.

No binary: six draws written out here, each missing in one way, and the
table's counts and medians worked out by hand:

- thermal_expansion 5e-5 read 5.2e-5: within 15 % (reading / truth 1.04);
- thermal_expansion 4e-5 read 5e-5: named, off (1.25);
- thermal_expansion 3e-5 unnamed, a hull_compressibility named instead: another named;
- thermal_expansion 6e-5 unnamed, nothing else: none in its place;
- thermal_expansion 2e-5 not identifiable (z 2): not counted;
- depth_lag 2.0 s hidden on a 2.3 s sensor read 1.9 s: off against the sensor's lag (0.826), though within
  15 % of the hidden part - the benchmark's truth for a depth lag is the sensor's.

Expected rows: thermal_expansion 4 identifiable, 1 within, 1 off, 1 another (hull_compressibility 1), 1 none,
reading / truth median 1.145 of 2, forced fit median 1.000 of 4; depth_lag 1, 0, 1, 0, 0, 0.826 (1).
"""
import os
import sys


def draw(truth, findings, judged, flight=None):
    return {'ok': True, 'case': '+'.join(truth), 'truth': truth, 'flight': flight or {},
            'findings': [[e, v, None, None, False] for e, v in findings.items()],
            'identifiability': judged}


def judged(value, z):
    return {'value': value, 'z': z, 'identifiable': z >= 3.6}


def main():
    sys.path.insert(0, sys.argv[1])
    import diagnose_truth_coverage as coverage
    import identifiability
    results = [
        draw({'thermal_expansion': 5e-5}, {'thermal_expansion': 5.2e-5}, {'thermal_expansion': judged(5e-5, 6.0)}),
        draw({'thermal_expansion': 4e-5}, {'thermal_expansion': 5e-5}, {'thermal_expansion': judged(4e-5, 5.0)}),
        draw({'thermal_expansion': 3e-5}, {'hull_compressibility': 2e-10}, {'thermal_expansion': judged(3e-5, 4.0)}),
        draw({'thermal_expansion': 6e-5}, {}, {'thermal_expansion': judged(6e-5, 4.5)}),
        draw({'thermal_expansion': 2e-5}, {}, {'thermal_expansion': judged(2e-5, 2.0)}),
        draw({'depth_lag': 2.0}, {'depth_lag': 1.9}, {'depth_lag': judged(1.9, 8.0)}, {'depth_sensor_lag_s': 2.3}),
    ]
    lines, rows = identifiability.misses_table(results, coverage.score, coverage.true_value, coverage.VERTICAL)
    print('\n'.join(lines))
    failures = []
    te, lag = rows.get('thermal_expansion'), rows.get('depth_lag')
    got = (te['identifiable'], te['within'], te['off'], te['competitor'], te['unnamed'])
    if got != (4, 1, 1, {'hull_compressibility': 1}, 1):
        failures.append('thermal_expansion counts %s' % (got,))
    if '| 1.145 (2) | 1.000 (4) |' not in next(line for line in lines if line.startswith('| thermal_expansion')):
        failures.append('thermal_expansion medians')
    got = (lag['identifiable'], lag['within'], lag['off'], lag['unnamed'])
    if got != (1, 0, 1, 0):
        failures.append('depth_lag counts %s' % (got,))
    if '| 0.826 (1) |' not in next(line for line in lines if line.startswith('| depth_lag')):
        failures.append('depth_lag reading against the sensor lag')
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS the misses told apart')
    return 0


if __name__ == '__main__':
    sys.exit(main())
