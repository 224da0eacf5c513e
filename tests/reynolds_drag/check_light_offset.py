#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A light buoyancy offset sized right once the model's drag follows the Reynolds number.

One log of the independent truth (tools/science/truth), shallow variant, seed 8:
a buoyancy offset of -60 g, the truth's skin friction falling with speed with
its drawn exponent (0.174, from the truth's own JSON). Fitted with the offset
and the CTD's density (`--fit buoyancy_offset,water_density`, glider-diagnose
as a black box):

- with the model's drag at every speed the file's (`--drag-reynolds-exponent 0`,
  the model before this term) the offset reads about -69 g and its 95 %
  interval misses -60 g: a light glider climbs fast and dives slow, where a
  drag that falls with speed makes it look lighter still;
- with the truth's exponent the interval holds -60 g;
- with the default (the documented prior, 0.1) the reading is nearer -60 g
  than without the term.
"""
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import diagnose_log, findings, fly  # noqa: E402

HIDDEN = -60.0


def offset(program, log, vehicle, extra):
    document = diagnose_log(program, log, vehicle, ['--fit', 'buoyancy_offset,water_density'] + extra)
    found = findings(document)
    if 'buoyancy_offset' not in found:
        sys.exit('FAIL no buoyancy_offset fitted (%s)' % extra)
    f = found['buoyancy_offset']
    return f['value'], f['ci95'][0], f['ci95'][1], document.get('drag_reynolds', {}).get('exponent')


def main():
    truth, program, vehicle, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    log = os.path.join(out, 'light_offset.csv')
    truth_json = os.path.join(out, 'light_offset.json')
    fly(truth, 'shallow', 8, {'buoyancy_offset': HIDDEN}, log, truth_json=truth_json)
    with open(truth_json) as f:
        exponent = json.load(f)['unmodelled']['drag_reynolds_exponent']
    failures = []
    off = offset(program, log, vehicle, ['--drag-reynolds-exponent', '0'])
    true_n = offset(program, log, vehicle, ['--drag-reynolds-exponent', '%.9g' % exponent])
    prior = offset(program, log, vehicle, [])
    for name, (value, low, high, n) in (('without the term', off), ('the truth\'s exponent', true_n),
                                        ('the prior', prior)):
        print('%s (n = %s): %.2f g [%.2f, %.2f], hidden %.1f g' % (name, n, value, low, high, HIDDEN))
    if off[1] <= HIDDEN <= off[2]:
        failures.append('without the term the interval holds the truth: the log no longer shows the bias')
    if not true_n[1] <= HIDDEN <= true_n[2]:
        failures.append('with the truth\'s exponent %.3f the interval [%.2f, %.2f] misses %.1f g' % (
            exponent, true_n[1], true_n[2], HIDDEN))
    if not abs(prior[0] - HIDDEN) < abs(off[0] - HIDDEN) - 2.0:
        failures.append('the prior reads %.2f g, not nearer than %.2f g by 2 g' % (prior[0], off[0]))
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS the Reynolds drag sizes the light offset')
    return 0


if __name__ == '__main__':
    sys.exit(main())
