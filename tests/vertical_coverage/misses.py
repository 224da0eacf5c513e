#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Where a named finding's 95 % interval misses its truth, and by how many of its own half-widths.

Reads a --details file of benchmarks/diagnose_truth_coverage.py (the benchmark's own scoring of what a finding
measures: benchmarks' true_value) and prints, per effect, named / covered and for each miss the draw, the
truth, the reading, its interval and the miss in half-widths (the distance from the reading to the truth over
the half-width on the truth's side: 1 is the interval's end).

usage: misses.py DETAILS.json [--effects a,b]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'benchmarks'))
import diagnose_truth_coverage as bench  # noqa: E402


def misses(results, effects=None):
    """[(effect, draw, truth, value, low, high, half-widths off)] of every named finding, and per-effect counts."""
    rows, counts = [], {}
    for r in results:
        if not r.get('ok'):
            continue
        found = {e: (v, lo, hi) for e, v, lo, hi, _ in r['findings']}
        for effect, hidden in r['truth'].items():
            if effects and effect not in effects:
                continue
            truth = bench.true_value(r, effect, hidden)
            c = counts.setdefault(effect, [0, 0, 0])
            c[0] += 1
            if effect not in found or found[effect][1] is None:
                continue
            v, lo, hi = found[effect]
            c[1] += 1
            half = (hi - v) if truth > v else (v - lo)
            off = abs(truth - v) / half if half > 0 else float('inf')
            c[2] += lo <= truth <= hi
            rows.append((effect, r, truth, v, lo, hi, off))
    return rows, counts


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('details', nargs='+')
    p.add_argument('--effects')
    p.add_argument('--all', action='store_true', help='print covered findings too')
    a = p.parse_args()
    results = []
    for path in a.details:
        with open(path) as f:
            results += json.load(f)
    effects = set(a.effects.split(',')) if a.effects else None
    rows, counts = misses(results, effects)
    print('| effect | hidden | named | covered |')
    print('|---|---|---|---|')
    for e, (h, n, c) in sorted(counts.items()):
        print('| %s | %d | %d | %d |' % (e, h, n, c))
    print()
    for effect, r, truth, v, lo, hi, off in sorted(rows, key=lambda x: (x[0], -x[6])):
        if off <= 1.0 and not a.all:
            continue
        others = ','.join(e for e, *_ in r['findings'] if e != effect and e not in bench.INPUTS)
        print('%-24s %-40s %s seed %d truth %.4g read %.4g [%.4g, %.4g] off %.2f half-widths; beside: %s' % (
            effect, r['case'], r['variant'], r['seed'], truth, v, lo, hi, off, others or '-'))


if __name__ == '__main__':
    main()
