#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A finding's interval holds the reading of a partner the selection did not name.

Two logs of the independent truth (tools/science/truth), fixed draws of the
deep variant, diagnosed as a black box (`glider-diagnose --plane vertical
--json`):

- a buoyancy offset of -13.2 g beside a hull compressibility of 0.95e-10 /Pa
  too small to pass the held-out margins: the offset is named at about
  -10.9 g, and its interval conditional on the selected model alone,
  [-13.03, -8.80] g, misses the truth (the code before this rule reported
  that interval). The interval must hold -13.2 g, say which partner widened
  it (`ci95_holds_with`) and keep the conditional one (`ci95_conditional`).
- a buoyancy offset of +48.2 g alone: the joint fits with its aliases see
  nothing, and the interval stays the conditional one (no `ci95_holds_with`).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import findings, fly_and_diagnose  # noqa: E402


def diagnose(truth, program, vehicle, out, seed, effects):
    """A deep draw of 6 yos with the hidden `effects`: its findings by effect."""
    return findings(fly_and_diagnose(truth, program, vehicle, out, 'aliased', 'deep', seed, effects))


def main():
    truth, program, vehicle, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    hidden = -13.1702753
    found = diagnose(truth, program, vehicle, out, 315428864847003000,
                     {'buoyancy_offset': hidden, 'hull_compressibility': 9.47492903e-11})
    offset = found.get('buoyancy_offset')
    if offset is None:
        failures.append('buoyancy_offset not named beside a small compressibility')
    else:
        low, high = offset['ci95']
        print('offset beside a compressibility: %.2f g [%.2f, %.2f], conditional %s, holds with %s (truth %.2f)' % (
            offset['value'], low, high, offset.get('ci95_conditional'), offset.get('ci95_holds_with'), hidden))
        if not low <= hidden <= high:
            failures.append('interval [%.2f, %.2f] misses the hidden %.2f g' % (low, high, hidden))
        if 'hull_compressibility' not in (offset.get('ci95_holds_with') or []):
            failures.append('ci95_holds_with does not name hull_compressibility')
        conditional = offset.get('ci95_conditional')
        if not conditional or conditional[0] <= hidden <= conditional[1]:
            failures.append('the conditional interval %s should be stated and miss the truth here' % conditional)
    alone = diagnose(truth, program, vehicle, out, 2932609412748375924, {'buoyancy_offset': 48.2349071})
    single = alone.get('buoyancy_offset')
    if single is None:
        failures.append('a lone buoyancy offset of +48 g not named')
    else:
        print('offset alone: %.2f g %s, holds with %s' % (single['value'], single['ci95'], single.get('ci95_holds_with')))
        if single.get('ci95_holds_with'):
            failures.append('a lone offset widened by %s: nothing else is hidden' % single['ci95_holds_with'])
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS aliased partner held in the interval')
    return 0


if __name__ == '__main__':
    sys.exit(main())
