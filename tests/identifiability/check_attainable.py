#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""What the logs allow of "within 15 %" (benchmarks/identifiability.py, attainable_within and
attainable_table): the chance an unbiased reading with standard error size / z lands within 15 % of the
size, P(|N(0, 1)| < 0.15 z), and its sum over a coverage run's identifiable draws.

Checked against the normal distribution's own quantiles (0.95 at z = 1.96 / 0.15, the SIZEABLE bound;
0.90 at 1.645 / 0.15; 0.4113 at the IDENTIFIABLE bound, 2 Phi(0.15 x 3.605) - 1) and on a hand-made run
of four draws whose answer is counted by hand. No binary.

  check_attainable.py BENCHMARKS_DIR
"""
import math
import sys


def main(benchmarks):
    sys.path.insert(0, benchmarks)
    import diagnose_truth_coverage as coverage
    import identifiability as measure
    failures = []
    for z, want in ((0.0, 0.0), (1.96 / 0.15, 0.95), (1.645 / 0.15, 0.90), (measure.Z_IDENTIFIABLE, 0.4113)):
        got = measure.attainable_within(z)
        print('z %.2f: %.4f (want %.4f)' % (z, got, want))
        if not abs(got - want) < 2e-4:
            failures.append('attainable_within(%.3f) = %.4f, not %.4f' % (z, got, want))
    if measure.attainable_within(None) is not None:
        failures.append('a draw not judged has a number')

    def draw(value, z, identifiable, sizeable):
        return {'ok': True, 'case': 'drag_change', 'truth': {'drag_change': 1.2},
                'findings': [['drag_change', value, value - 0.01, value + 0.01, False]] if value else [],
                'identifiability': {'drag_change': {'z': z, 'identifiable': identifiable, 'sizeable': sizeable}}}
    # within 15 % of a 0.2 change: 1.17..1.23. Counted: identifiable draws 3 (the z 2.0 one is not), within 2
    # (1.21 and 1.19; 1.30 is not, the unnamed one not judged since not identifiable), sizeable 1 (z 20, within).
    run = [draw(1.21, 20.0, True, True), draw(1.19, 5.0, True, False), draw(1.30, 8.0, True, False),
           draw(None, 2.0, False, False)]
    lines, rows = measure.attainable_table(run, coverage.score, ['drag_change'])
    print('\n'.join(lines))
    row = rows.get('drag_change', {})
    allowed = sum(measure.attainable_within(z) for z in (20.0, 5.0, 8.0))
    want = {'identifiable': 3, 'within': 2, 'sizeable': 1, 'sizeable_within': 1}
    if any(row.get(k) != v for k, v in want.items()) or not math.isclose(row.get('attainable', -1), allowed):
        failures.append('table row %s, not %s with %.4f allowed' % (row, want, allowed))
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS what the logs allow counted')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1]))
