#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Offline: a finding's interval holding its reading beside a screened partner wherever the held-out yos do not
reject that joint fit (read_beside's held-out RMS, both views, no worse than the selection's; or seen), scored
against the benchmark's truth on kept logs. Each log's full diagnosis (glider-diagnose --json, the binary given) is
cached as LOG.diag.json beside it. Prints per effect and variant: named, covered by the conditional interval / by the
binary's / by the rule offline, and widths. --gain asks a held-out gain of the joint fit; --partner-range
EFFECT=LO:HI admits a partner's joint reading only inside that range (the rule of docs/science.md "The partner's
size beside a finding"), --partner-range none: no range.

usage: beside_rule.py DIAGNOSE VEHICLES_DIR LOGDIR DETAILS.json [--gain G] [--partner-range EFFECT=LO:HI ...]
"""
import argparse
import json
import math
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


def conditional(finding):
    """The finding's interval before any reading beside was held (the JSON's ci95_conditional where one was)."""
    return finding['ci95_conditional'] if finding.get('ci95_holds_with') else finding['ci95']


Z95 = 1.96  # fitting_core::kZ95, the sigmas behind the JSON's intervals
# flight_model.cpp's kInfo: each effect's nominal and typical size (EffectInfo::scale).
TYPICAL = {'buoyancy_offset': (0.0, 20.0), 'drag_change': (1.0, 0.1), 'hull_compressibility': (0.0, 1e-10),
           'thermal_expansion': (0.0, 1e-5), 'vertical_water_velocity': (0.0, 0.01), 'water_density': (0.0, 1.0),
           'pitch_trim_offset': (0.0, 0.01), 'pump_lag': (0.0, 5.0), 'lift_change': (1.0, 0.1),
           'depth_lag': (0.0, 1.0)}


def under_prior(finding, b, factor):
    """The finding's reading beside the partner with a Gaussian prior on the partner's size (sd: `factor` times its
    typical size), from the conditional and joint readings (linear: the partner's reading shrunk by
    k = s^2 / (s^2 + sigma_partner^2), the finding's shift and its variance beyond the conditional's by the same k)."""
    clo, chi = conditional(finding)
    sigma_c = (chi - clo) / (2 * Z95)
    a_c = finding['value']
    a_j = b['value']
    sigma_j = (b['ci95'][1] - b['value']) / Z95
    sigma_p = (b['partner_ci95'][1] - b['partner_ci95'][0]) / (2 * Z95)
    sd = factor * TYPICAL[b['partner']][1]
    k = sd * sd / (sd * sd + sigma_p * sigma_p)
    a = a_c + k * (a_j - a_c)
    sigma = math.sqrt(sigma_c * sigma_c + k * max(0.0, sigma_j * sigma_j - sigma_c * sigma_c))
    low = a - Z95 * sigma
    if finding['effect'] in ('pump_lag', 'depth_lag'):
        low = max(0.0, low)
    return low, a + Z95 * sigma


def mixture(intervals):
    """The central 95 % of an equal-weight mixture of normals, each given by its 95 % interval."""
    parts = [((lo + hi) / 2, max((hi - lo) / (2 * Z95), 1e-300)) for lo, hi in intervals]

    def cdf(x):
        return sum(0.5 * (1 + math.erf((x - m) / (s * math.sqrt(2)))) for m, s in parts) / len(parts)

    def quantile(q):
        lo = min(m - 10 * s for m, s in parts)
        hi = max(m + 10 * s for m, s in parts)
        for _ in range(200):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if cdf(mid) < q else (lo, mid)
        return (lo + hi) / 2
    return quantile(0.025), quantile(0.975)


def held(finding, beside, gain=0.0, ranges=None, prior=0.0, mix=False):
    """The conditional interval with every screened partner's joint reading that is seen or that the held-out yos
    do not reject (gain 0), or prefer by at least this relative gain (both views); with `ranges`, only partners whose
    joint reading is inside their range {effect: (lo, hi)} (an effect not named: any)."""
    lo, hi = conditional(finding)
    parts = [(lo, hi)]
    keep = 1.0 - gain
    for b in beside:
        if b['effect'] != finding['effect']:
            continue
        low, high = (ranges or {}).get(b['partner'], (-math.inf, math.inf))
        if not low <= b['partner_value'] <= high:
            continue
        if (b['partner_seen'] and gain == 0.0) or (
                b['heldout_rms_depth_rate_m_s'] <= keep * b['selected_heldout_rms_depth_rate_m_s'] and
                b['heldout_block_rms_depth_rate_m_s'] <= keep * b['selected_heldout_block_rms_depth_rate_m_s']):
            blo, bhi = under_prior(finding, b, prior) if prior > 0.0 else b['ci95']
            lo, hi = min(lo, blo), max(hi, bhi)
            parts.append((blo, bhi))
    if mix and len(parts) > 1:  # never narrower than the conditional interval
        mlo, mhi = mixture(parts)
        return min(parts[0][0], mlo), max(parts[0][1], mhi)
    return lo, hi


def parse_ranges(items):
    out = {}
    for item in items or []:
        if item == 'none':
            continue
        effect, span = item.split('=')
        low, high = span.split(':')
        out[effect] = (float(low), float(high))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('diagnose')
    p.add_argument('vehicles')
    p.add_argument('logdir')
    p.add_argument('details', nargs='+')
    p.add_argument('--gain', type=float, default=0.0, help='relative held-out gain the joint fit must show')
    p.add_argument('--partner-range', action='append', help='EFFECT=LO:HI: admit a partner read inside only')
    p.add_argument('--mixture', action='store_true',
                   help='the central 95 %% of the equal-weight mixture of the conditional and held readings')
    p.add_argument('--partner-prior', type=float, default=0.0,
                   help="a Gaussian prior on the partner's size, sd this many typical sizes (0: none)")
    a = p.parse_args()
    ranges = parse_ranges(a.partner_range)
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
                clo, chi = conditional(f)
                lo, hi = f['ci95']
                nlo, nhi = held(f, d.get('read_beside', []), a.gain, ranges, a.partner_prior, a.mixture)
                if f.get('ci95_holds_with'):  # a later widening (another depth lag form, the stall's lift) stays
                    olo, ohi = held(f, d.get('read_beside', []))
                    nlo, nhi = (lo, nhi) if lo < olo else (nlo, nhi)
                    nlo, nhi = (nlo, hi) if hi > ohi else (nlo, nhi)
                hidden = f['effect'] in r['truth']
                truth = bench.true_value(r, f['effect'], r['truth'][f['effect']]) if hidden else None
                rows.append({'effect': f['effect'], 'variant': r['variant'], 'hidden': hidden,
                             'conditional': hidden and clo <= truth <= chi,
                             'before': hidden and lo <= truth <= hi, 'after': hidden and nlo <= truth <= nhi,
                             'width': (nhi - nlo) / (hi - lo) if hi > lo else 1.0,
                             'vs_conditional': (nhi - nlo) / (chi - clo) if chi > clo else 1.0,
                             'binary_vs_conditional': (hi - lo) / (chi - clo) if chi > clo else 1.0,
                             'case': r['case'], 'seed': r['seed']})
    print('| effect | variant | named (hidden) | covered: conditional | binary | rule | rule/binary width: narrower, '
          'median (min) | rule/conditional: wider, median (max) |')
    print('|---|---|---|---|---|---|---|---|')
    for effect in bench.VERTICAL:
        for variant in ('shallow', 'deep'):
            rs = [x for x in rows if x['effect'] == effect and x['variant'] == variant and x['hidden']]
            if not rs:
                continue
            ws, vs = [x['width'] for x in rs], [x['vs_conditional'] for x in rs]
            print('| %s | %s | %d | %d | %d | %d | %d, x%.2f (x%.2f) | %d, x%.2f (x%.2f) |' % (
                effect, variant, len(rs), sum(x['conditional'] for x in rs), sum(x['before'] for x in rs),
                sum(x['after'] for x in rs), sum(w < 1.0 - 1e-9 for w in ws), statistics.median(ws), min(ws),
                sum(v > 1.0 + 1e-9 for v in vs), statistics.median(vs), max(vs)))
    vs, bs = [x['vs_conditional'] for x in rows], [x['binary_vs_conditional'] for x in rows]
    ws = [x['width'] for x in rows]
    print('all findings %d: wider than the conditional: the binary %d (max x%.2f), the rule %d (max x%.2f); the rule '
          'narrower than the binary %d' % (len(rows), sum(v > 1.0 + 1e-9 for v in bs), max(bs or [1.0]),
                                           sum(v > 1.0 + 1e-9 for v in vs), max(vs or [1.0]),
                                           sum(w < 1.0 - 1e-9 for w in ws)))
    spur = [x for x in rows if not x['hidden']]
    print('findings of effects not hidden: %d (wider than conditional %d)' % (
        len(spur), sum(x['vs_conditional'] > 1.0 + 1e-9 for x in spur)))
    for x in rows:
        if x['before'] != x['after']:
            print('  %s: %s %s %s seed %d (width x%.2f of the binary\'s)' % (
                'now covered' if x['after'] else 'LOST', x['effect'], x['variant'], x['case'], x['seed'], x['width']))


if __name__ == '__main__':
    main()
