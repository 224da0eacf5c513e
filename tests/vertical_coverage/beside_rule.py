#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Offline: a finding's interval holding its reading beside a screened partner wherever the held-out yos do not
reject that joint fit (read_beside's held-out RMS, both views, no worse than the selection's), scored against the
benchmark's truth on kept logs. Each log's full diagnosis (glider-diagnose --json, the binary given) is cached as
LOG.diag.json beside it. Prints per effect and variant: named, covered now / with the rule, width after/before.

usage: beside_rule.py DIAGNOSE VEHICLES_DIR LOGDIR DETAILS.json
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'benchmarks'))
import diagnose_truth_coverage as bench  # noqa: E402


def diagnosis(diagnose, log, vehicle):
    cache = log[:-4] + '.diag.json'
    if not os.path.exists(cache):
        out = subprocess.run(['nice', '-n', '19', diagnose, log, '--vehicle', vehicle, '--plane', 'vertical',
                              '--json'], capture_output=True, text=True, timeout=600)
        with open(cache, 'w') as f:
            f.write(out.stdout)
    with open(cache) as f:
        return json.load(f)


def held(finding, beside, gain=0.0):
    """The interval with every screened partner's joint reading the held-out yos do not reject (gain 0), or prefer
    by at least this relative gain (both views)."""
    lo, hi = finding['ci95']
    keep = 1.0 - gain
    for b in beside:
        if b['effect'] != finding['effect']:
            continue
        if b['heldout_rms_depth_rate_m_s'] <= keep * b['selected_heldout_rms_depth_rate_m_s'] and \
                b['heldout_block_rms_depth_rate_m_s'] <= keep * b['selected_heldout_block_rms_depth_rate_m_s']:
            lo, hi = min(lo, b['ci95'][0]), max(hi, b['ci95'][1])
    return lo, hi


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('diagnose')
    p.add_argument('vehicles')
    p.add_argument('logdir')
    p.add_argument('details', nargs='+')
    p.add_argument('--gain', type=float, default=0.0, help='relative held-out gain the joint fit must show')
    a = p.parse_args()
    rows = []
    for path in a.details:
        with open(path) as f:
            results = json.load(f)
        for r in results:
            if not r.get('ok'):
                continue
            name = '%s_%d' % (r['case'].replace('+', '-'), r['seed'])
            vehicle = os.path.join(a.vehicles, 'slocum_we01.toml' if r['variant'] == 'deep' else 'slocum_shallow.toml')
            d = diagnosis(a.diagnose, os.path.join(a.logdir, name + '.csv'), vehicle)
            for f in d['findings']:
                if not f.get('fitted', True) or not f.get('ci95') or f['effect'] in bench.INPUTS:
                    continue
                lo, hi = f['ci95']
                nlo, nhi = held(f, d.get('read_beside', []), a.gain)
                hidden = f['effect'] in r['truth']
                truth = bench.true_value(r, f['effect'], r['truth'][f['effect']]) if hidden else None
                rows.append({'effect': f['effect'], 'variant': r['variant'], 'hidden': hidden,
                             'before': hidden and lo <= truth <= hi, 'after': hidden and nlo <= truth <= nhi,
                             'width': (nhi - nlo) / (hi - lo) if hi > lo else 1.0, 'case': r['case'], 'seed': r['seed']})
    print('| effect | variant | named (hidden) | covered before | with the rule | widened | width after/before: median (max) |')
    print('|---|---|---|---|---|---|---|')
    for effect in bench.VERTICAL:
        for variant in ('shallow', 'deep'):
            rs = [x for x in rows if x['effect'] == effect and x['variant'] == variant and x['hidden']]
            if not rs:
                continue
            ws = [x['width'] for x in rs]
            print('| %s | %s | %d | %d | %d | %d | x%.2f (x%.2f) |' % (
                effect, variant, len(rs), sum(x['before'] for x in rs), sum(x['after'] for x in rs),
                sum(w > 1.0 for w in ws), statistics.median(ws), max(ws)))
    spur = [x for x in rows if not x['hidden']]
    print('findings of effects not hidden: %d (widened %d)' % (len(spur), sum(x['width'] > 1.0 for x in spur)))
    for x in rows:
        if x['before'] != x['after']:
            print('  now covered: %s %s %s seed %d (width x%.2f)' % (x['effect'], x['variant'], x['case'], x['seed'],
                                                                      x['width']))


if __name__ == '__main__':
    main()
