#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Per hidden effect and variant, split by identifiability: named, within 15 %, covered - and of the draws not named,
how many are on a side of a stated ambiguity and how many are silent (issue 26: where the log cannot tell, the
finding must say so). docs/science.md, "Why the lift change and the water's vertical velocity are seldom named".

Input: a run of benchmarks/diagnose_truth_coverage.py saved with --identifiability fit --details D.json. Named, within
and covered are the benchmark's own (its `score`); identifiable is the forced fit's z >= 3.6 (benchmarks/
identifiability.py); "stated": the effect is on a side of a pair the diagnosis stated ambiguous; "silent": neither
named nor stated.

  tabulate_silent.py D.json [--effects lift_change,vertical_water_velocity]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'benchmarks'))
import diagnose_truth_coverage as coverage  # noqa: E402  (the benchmark's scoring, not a copy of it)

COUNTS = ('hidden', 'named', 'within', 'covered', 'stated', 'silent')


def counts(results, effects=None):
    """(effect, variant, identifiable: True / False / None) -> {hidden, named, within, covered, stated, silent}."""
    rows = {}
    for r in results:
        per, _, _ = coverage.score(r)
        for effect, (named, within, covered, _) in per.items():
            if effects and effect not in effects:
                continue
            judged = r.get('identifiability', {}).get(effect, {}).get('identifiable')
            c = rows.setdefault((effect, r['variant'], judged), dict.fromkeys(COUNTS, 0))
            stated = effect in r.get('stated_ambiguous', [])
            c['hidden'] += 1
            c['named'] += bool(named)
            c['within'] += bool(within)
            c['covered'] += covered is True
            c['stated'] += not named and stated
            c['silent'] += not named and not stated
    return rows


def table(rows):
    lines = ['| effect | variant | identifiable | hidden | named | within 15 % | covered | not named: stated | silent |',
             '|---|---|---|---|---|---|---|---|---|']
    order = {True: 0, False: 1, None: 2}
    for (effect, variant, judged), c in sorted(rows.items(), key=lambda kv: (kv[0][0], kv[0][1], order[kv[0][2]])):
        lines.append('| %s | %s | %s | %s |' % (effect, variant, {True: 'yes', False: 'no', None: 'not judged'}[judged],
                                              ' | '.join(str(c[k]) for k in COUNTS)))
    return lines


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('details')
    p.add_argument('--effects', help='comma list (default: every hidden effect)')
    args = p.parse_args()
    with open(args.details) as f:
        results = [r for r in json.load(f) if r.get('ok')]
    effects = set(args.effects.split(',')) if args.effects else None
    print('\n'.join(table(counts(results, effects))))
    return 0


if __name__ == '__main__':
    sys.exit(main())
