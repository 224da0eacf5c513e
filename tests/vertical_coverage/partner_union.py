#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Offline test of one interval rule on kept benchmark logs: a named finding whose near-degenerate partner is not
named takes the union of its interval and its interval in the joint fit with the partner beside (the reading
unconditional on the partner being nominal).

Pairs: drag_change <-> lift_change, vertical_water_velocity <-> buoyancy_offset. For every draw of a --details
file whose logs were kept (--keep --out DIR), each such finding is fitted again with `glider-diagnose --fit` (the
draw's named effects + the partner) and scored before/after against the benchmark's truth: covered, the
interval's width (after over before), on deep and shallow logs. Findings are unchanged by construction (an
interval rule).

usage: partner_union.py DIAGNOSE VEHICLES_DIR LOGDIR DETAILS.json [--variant deep|shallow]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'benchmarks'))
import diagnose_truth_coverage as bench  # noqa: E402

PARTNER = {'drag_change': 'lift_change', 'lift_change': 'drag_change',
           'vertical_water_velocity': 'buoyancy_offset', 'buoyancy_offset': 'vertical_water_velocity'}


def joint_interval(diagnose, log, vehicle, effects, effect):
    out = subprocess.run(['nice', '-n', '19', diagnose, log, '--vehicle', vehicle, '--plane', 'vertical', '--json',
                          '--fit', ','.join(effects)], capture_output=True, text=True, timeout=600)
    if out.returncode != 0:
        return None
    for f in json.loads(out.stdout).get('findings', []):
        if f['effect'] == effect and f.get('ci95'):
            return f['value'], f['ci95'][0], f['ci95'][1]
    return None


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('diagnose')
    p.add_argument('vehicles')
    p.add_argument('logdir')
    p.add_argument('details')
    p.add_argument('--variant', choices=('deep', 'shallow'))
    a = p.parse_args()
    with open(a.details) as f:
        results = json.load(f)
    rows = []
    for r in results:
        if not r.get('ok') or (a.variant and r['variant'] != a.variant):
            continue
        named = {e: (v, lo, hi) for e, v, lo, hi, _ in r['findings']}
        for effect, (v, lo, hi) in named.items():
            partner = PARTNER.get(effect)
            if partner is None or partner in named or lo is None:
                continue
            name = '%s_%d' % (r['case'].replace('+', '-'), r['seed'])
            vehicle = os.path.join(a.vehicles, 'slocum_we01.toml' if r['variant'] == 'deep' else 'slocum_shallow.toml')
            joint = joint_interval(a.diagnose, os.path.join(a.logdir, name + '.csv'), vehicle,
                                   list(named) + [partner], effect)
            if joint is None:
                continue
            new_lo, new_hi = min(lo, joint[1]), max(hi, joint[2])
            hidden = effect in r['truth']
            truth = bench.true_value(r, effect, r['truth'][effect]) if hidden else bench.nominal(effect)
            rows.append({'effect': effect, 'variant': r['variant'], 'case': r['case'], 'seed': r['seed'],
                         'hidden': hidden, 'truth': truth, 'before': (lo <= truth <= hi),
                         'after': (new_lo <= truth <= new_hi), 'width': (new_hi - new_lo) / (hi - lo),
                         'partner_hidden': partner in r['truth'], 'joint': joint})
    print('| effect | variant | named, partner unnamed (hidden) | covered before | after | width after/before: median (max) |')
    print('|---|---|---|---|---|---|')
    for effect in PARTNER:
        for variant in ('shallow', 'deep'):
            rs = [x for x in rows if x['effect'] == effect and x['variant'] == variant and x['hidden']]
            if not rs:
                continue
            ws = [x['width'] for x in rs]
            print('| %s | %s | %d | %d | %d | x%.2f (x%.2f) |' % (
                effect, variant, len(rs), sum(x['before'] for x in rs), sum(x['after'] for x in rs),
                statistics.median(ws), max(ws)))
    for x in rows:
        if x['hidden'] and x['before'] != x['after']:
            print('  now covered: %s %s %s seed %d truth %.4g joint %.4g [%.4g, %.4g] (partner hidden: %s)' % (
                x['effect'], x['variant'], x['case'], x['seed'], x['truth'], *x['joint'], x['partner_hidden']))


if __name__ == '__main__':
    main()
