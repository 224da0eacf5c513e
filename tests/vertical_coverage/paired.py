#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Two --details runs of benchmarks/diagnose_truth_coverage.py on the same seed (the same logs), side by side per
effect: named / within 15 % / covered / spurious draws / clean logs with no finding for each, the draws whose
findings (effects named) differ, and each interval's width in the second run over the first's (median, max, how many
wider, how many narrower and the least) for the findings both runs name.

usage: paired.py BEFORE.json AFTER.json
"""
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'benchmarks'))
import diagnose_truth_coverage as bench  # noqa: E402


def tallies(results):
    per, spurious, clean, draws = {}, 0, 0, 0
    for r in results:
        if not r.get('ok'):
            continue
        draws += 1
        scored, spur, _ = bench.score(r)
        spurious += bool(spur)
        clean += r['case'] == 'none' and not [f for f in r['findings'] if f[0] not in bench.INPUTS]
        for effect, (n, w, c, _) in scored.items():
            t = per.setdefault(effect, [0, 0, 0, 0, 0])
            t[0] += 1
            t[1] += n
            t[2] += w
            t[3] += c is not None
            t[4] += bool(c)
    return per, spurious, clean, draws


def widths(before, after):
    """Per effect: after/before widths of the findings both name, on the same draw."""
    out = {}
    b = {(r['case'], r['seed']): r for r in before if r.get('ok')}
    for r in after:
        if not r.get('ok') or (r['case'], r['seed']) not in b:
            continue
        old = {e: (lo, hi) for e, _, lo, hi, _ in b[(r['case'], r['seed'])]['findings'] if lo is not None}
        for e, _, lo, hi, _ in r['findings']:
            if lo is None or e not in old or e in bench.INPUTS or not old[e][1] > old[e][0]:
                continue
            out.setdefault(e, []).append((hi - lo) / (old[e][1] - old[e][0]))
    return out


def changed(before, after):
    b = {(r['case'], r['seed']): r for r in before if r.get('ok')}
    diff = []
    for r in after:
        key = (r['case'], r['seed'])
        if r.get('ok') and key in b:
            if sorted(f[0] for f in r['findings']) != sorted(f[0] for f in b[key]['findings']):
                diff.append(key)
    return diff, len([r for r in after if r.get('ok') and (r['case'], r['seed']) in b])


def main():
    with open(sys.argv[1]) as f:
        before = json.load(f)
    with open(sys.argv[2]) as f:
        after = json.load(f)
    pb, sb, cb, db = tallies(before)
    pa, sa, ca, da = tallies(after)
    w = widths(before, after)
    print('| effect | hidden | named | within 15 % | covered | width after/before: median (max), wider; narrower (min) |')
    print('|---|---|---|---|---|---|')
    for e in bench.VERTICAL + bench.HEADING:
        if e not in pb and e not in pa:
            continue
        x, y = pb.get(e, [0] * 5), pa.get(e, [0] * 5)
        ws = w.get(e, [])
        print('| %s | %d | %d -> %d | %d -> %d | %d/%d -> %d/%d | %s |' % (
            e, x[0], x[1], y[1], x[2], y[2], x[4], x[3], y[4], y[3],
            'x%.2f (x%.2f), %d of %d; narrower %d (min x%.2f)' % (
                statistics.median(ws), max(ws), sum(v > 1.0 + 1e-9 for v in ws), len(ws),
                sum(v < 1.0 - 1e-9 for v in ws), min(ws))
            if ws else '-'))
    diff, both = changed(before, after)
    print('draws %d -> %d; spurious %d -> %d; clean logs with no finding %d -> %d; findings differ in %d of %d draws' % (
        db, da, sb, sa, cb, ca, len(diff), both))
    for case, seed in diff:
        print('  findings differ: %s seed %d' % (case, seed))


if __name__ == '__main__':
    main()
