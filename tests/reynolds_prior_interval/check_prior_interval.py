#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The Reynolds prior's uncertainty carried into the drag's interval.

glider-diagnose flies the skin friction's Reynolds exponent n = 0.1 (a prior)
where neither the user nor the vehicle file states one. The drag factor it
reads holds at the file's reference speed, so it moves with n by ln(V / V_ref)
over the speeds flown: a bias every yo shares, which the training intervals
and the held-out replicate cannot see (docs/science.md, "Method rule: the
Reynolds prior's uncertainty in the intervals"). The rule: the final model
fitted again at n + 0.05 (the prior's sigma), from the start the reading's own
fit started at ("The Reynolds prior's refit from the reading's own start"),
and each sigma combined with the shift.

A fresh log of the independent truth (tools/science/truth; the seed is drawn
fresh and printed, `--seed S` replays; a log whose glider flies near the
reference speed, where n hardly matters, is followed by another, three at most), deep variant
(WE01, reference speed 0.46 m/s: the glider flies well below it, where the
term matters most), drag_change hidden. Fitted with the drag and the CTD's
density (`--fit drag_change,water_density`, glider-diagnose as a black box):

- with the prior the JSON states the sigma carried (0.05), and the drag's
  95 % half-width is hypot(h, 1.96 |k(0.15) - k(0.1)|), h the half-width with
  n = 0.1 asked for (a stated exponent: nothing added), k(n) the drag read
  with n asked for - within 15 % of the shift term;
- the values are the same either way (the rule moves intervals only).
"""
import argparse
import json
import math
import os
import random
import secrets
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import diagnose_log, findings, fly  # noqa: E402


def fitted(program, log, vehicle, extra):
    document = diagnose_log(program, log, vehicle, ['--fit', 'drag_change,water_density'] + extra)
    found = findings(document)
    if 'drag_change' not in found:
        sys.exit('FAIL no drag_change fitted (%s)' % extra)
    f = found['drag_change']
    return f['value'], f['ci95'][0], f['ci95'][1], document.get('drag_reynolds', {})


def main():
    p = argparse.ArgumentParser()
    p.add_argument('truth')
    p.add_argument('diagnose')
    p.add_argument('vehicle')
    p.add_argument('out')
    p.add_argument('--seed', type=int, help='replay this seed (default: fresh, printed)')
    args = p.parse_args()
    seed = args.seed if args.seed is not None else secrets.randbelow(2**31)
    print('seed %d (replay: --seed %d)' % (seed, seed))
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(seed)
    # A glider that flies near the reference speed hardly moves with the
    # exponent (ln(V / V_ref) ~ 0) and does not test the rule: up to three
    # logs from the seed, the first whose drag moves by 0.2 % per 0.05 of n.
    for attempt in range(3):
        log_seed = rng.randrange(2**31)
        drag = rng.uniform(1.1, 1.5)
        print('log %d: truth seed %d, hidden drag_change %.4f' % (attempt + 1, log_seed, drag))
        log = os.path.join(args.out, 'prior_interval.csv')
        truth_json = os.path.join(args.out, 'prior_interval.json')
        fly(args.truth, 'deep', log_seed, {'drag_change': drag}, log, truth_json=truth_json)
        with open(truth_json) as f:
            exponent = json.load(f)['unmodelled']['drag_reynolds_exponent']
        prior = fitted(args.diagnose, log, args.vehicle, [])
        asked = fitted(args.diagnose, log, args.vehicle, ['--drag-reynolds-exponent', '0.1'])
        moved = fitted(args.diagnose, log, args.vehicle, ['--drag-reynolds-exponent', '0.15'])
        for name, (value, low, high, reynolds) in (('prior', prior), ('n = 0.1 asked', asked),
                                                   ('n = 0.15 asked', moved)):
            print('  %s: drag %.4f [%.4f, %.4f] (exponent %s, sigma carried %s); truth %.4f, truth\'s n %.3f' % (
                name, value, low, high, reynolds.get('exponent'), reynolds.get('exponent_sigma_in_intervals'), drag,
                exponent))
        shift = 1.96 * abs(moved[0] - asked[0])
        if shift >= 0.002 * asked[0]:
            break
    failures = []
    if prior[3].get('exponent_sigma_in_intervals') != 0.05:
        failures.append('the prior\'s JSON does not state the sigma carried (0.05): %s' % prior[3])
    if asked[3].get('exponent_sigma_in_intervals') != 0.0:
        failures.append('an exponent asked for still carries a prior sigma: %s' % asked[3])
    if abs(prior[0] - asked[0]) > 1e-9 * abs(asked[0]):
        failures.append('the value moved: %.9g with the prior, %.9g with n = 0.1 asked' % (prior[0], asked[0]))
    h_asked = 0.5 * (asked[2] - asked[1])
    h_prior = 0.5 * (prior[2] - prior[1])
    expected = math.hypot(h_asked, shift)
    print('half-width: asked %.5f, prior %.5f, expected hypot(%.5f, %.5f) = %.5f' % (
        h_asked, h_prior, h_asked, shift, expected))
    if shift < 0.002 * asked[0]:
        failures.append('in three logs the exponent hardly moved the drag (last shift %.5f): the rule is untested' % shift)
    if abs(h_prior - expected) > 0.15 * shift:
        failures.append('the prior\'s half-width %.5f is not hypot(%.5f, %.5f) = %.5f within 15 %% of the shift' % (
            h_prior, h_asked, shift, expected))
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS the prior\'s uncertainty is in the interval')
    return 0


if __name__ == '__main__':
    sys.exit(main())
