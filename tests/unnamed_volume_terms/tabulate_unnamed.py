#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The statements of the hull's volume terms not named (glider-diagnose's `read_unnamed`), tabulated against the
truth of a coverage run (docs/science.md, "The hull's volume terms where not named").

Input: a run of benchmarks/diagnose_truth_coverage.py saved with --keep --out DIR --details D.json (any binary;
with --identifiability the identifiable split is shown). Each kept log is diagnosed again by GLIDER_DIAGNOSE
(`--plane vertical --json`); its findings are compared with the run's (same effects and values to the bit: the
statements change no finding), and per variant and volume term: hidden and named, hidden and not named (stated
seen / not seen, the stated interval holding the truth, by identifiability), and where the term is not hidden,
how often it was stated seen (a false "seen").

  tabulate_unnamed.py D.json DIR GLIDER_DIAGNOSE SOURCE_DIR [--save OUT.json]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import diagnose_log, vehicle_file  # noqa: E402

TERMS = ('hull_compressibility', 'thermal_expansion')


def diagnose_kept(r, directory, diagnose, source):
    name = '%s_%d' % (r['case'].replace('+', '-'), r['seed'])
    log = os.path.join(directory, name + '.csv')
    return diagnose_log(diagnose, log, vehicle_file(os.path.join(source, 'boards', 'vehicles'), r['variant']),
                        timeout=900)


def same_findings(r, document):
    ours = [(f['effect'], f['value']) for f in document['findings']]
    theirs = [(f[0], f[1]) for f in r['findings']]
    return ours == theirs


def tabulate(rows):
    lines = ['| variant | term | hidden | named | not named: stated | seen | its interval holds the truth |'
             ' identifiable unnamed: seen / held | not identifiable unnamed: seen / held |'
             ' not hidden: stated | stated seen (false) |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for variant in ('shallow', 'deep'):
        for term in TERMS:
            mine = [x for x in rows if x['variant'] == variant]
            hid = [x for x in mine if term in x['truth']]
            named = [x for x in hid if term in x['named']]
            unnamed = [x for x in hid if term not in x['named']]
            stated = [x for x in unnamed if term in x['unnamed']]
            seen = [x for x in stated if x['unnamed'][term]['seen']]
            held = [x for x in stated if x['unnamed'][term]['held']]
            ident = [x for x in stated if x['identifiable'].get(term) is True]
            noident = [x for x in stated if x['identifiable'].get(term) is False]
            other = [x for x in mine if term not in x['truth']]
            other_stated = [x for x in other if term in x['unnamed']]
            false_seen = [x for x in other_stated if x['unnamed'][term]['seen']]
            lines.append('| %s | %s | %d | %d | %d/%d | %d | %d/%d | %d/%d / %d | %d/%d / %d | %d/%d | %d/%d |' % (
                variant, term, len(hid), len(named), len(stated), len(unnamed), len(seen), len(held), len(stated),
                sum(x['unnamed'][term]['seen'] for x in ident), len(ident),
                sum(x['unnamed'][term]['held'] for x in ident),
                sum(x['unnamed'][term]['seen'] for x in noident), len(noident),
                sum(x['unnamed'][term]['held'] for x in noident),
                len(other_stated), len(other), len(false_seen), len(other_stated)))
    return lines


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('details')
    p.add_argument('directory')
    p.add_argument('diagnose')
    p.add_argument('source')
    p.add_argument('--save', help='every draw\'s row (JSON)')
    args = p.parse_args()
    with open(args.details) as f:
        results = [r for r in json.load(f) if r.get('ok')]
    rows, changed = [], []
    for k, r in enumerate(results, 1):
        document = diagnose_kept(r, args.directory, args.diagnose, args.source)
        if not same_findings(r, document):
            changed.append('%s %d: %s -> %s' % (r['case'], r['seed'], [(f[0], f[1]) for f in r['findings']],
                                               [(f['effect'], f['value']) for f in document['findings']]))
        unnamed = {}
        for u in document.get('read_unnamed', []):
            truth = r['truth'].get(u['effect'], 0.0)
            unnamed[u['effect']] = {'value': u['value'], 'ci95': u['ci95'], 'seen': u['seen'],
                                    'prior': u['ruled_out_by_prior'],
                                    'held': u['ci95'][0] is not None and u['ci95'][0] <= truth <= u['ci95'][1]}
        rows.append({'case': r['case'], 'seed': r['seed'], 'variant': r['variant'], 'truth': r['truth'],
                     'named': [f['effect'] for f in document['findings']], 'unnamed': unnamed,
                     'identifiable': {e: m.get('identifiable') for e, m in r.get('identifiability', {}).items()},
                     'z': {e: m.get('z') for e, m in r.get('identifiability', {}).items()}})
        print('\r%d of %d logs' % (k, len(results)), end='', file=sys.stderr, flush=True)
    print('', file=sys.stderr)
    print('\n'.join(tabulate(rows)))
    print('findings changed against the run\'s: %d of %d logs' % (len(changed), len(rows)))
    for c in changed:
        print('  ' + c)
    for x in rows:
        for term, u in x['unnamed'].items():
            if term in x['truth'] or u['seen']:
                print('  %s %d (%s): %s %+.3g [%s, %s] %s; truth %.3g, z %s' % (
                    x['case'], x['seed'], x['variant'], term, u['value'], *('%.3g' % v if v is not None else '-'
                                                                            for v in u['ci95']),
                    'ruled out by the prior' if u['prior'] else 'seen' if u['seen'] else 'not seen', x['truth'].get(term, 0.0),
                    '-' if x['z'].get(term) is None else '%.1f' % x['z'][term]))
    if args.save:
        with open(args.save, 'w') as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == '__main__':
    sys.exit(main())
