#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Why an identifiable buoyancy offset missed 15 %, draw by draw (issue 26, vertical plane; docs/science.md "Why the
buoyancy offset is not sized within 15 % where identifiable, by cause").

Reads a coverage run saved by `benchmarks/diagnose_truth_coverage.py --identifiability --details D.json` and
classifies each draw whose offset is identifiable (forced-fit z >= 3.6) and not named within 15 % of its truth:

- AMBIGUOUS_OTHER_SIDE: the diagnosis stated the offset ambiguous with the offset's reading on the stated other side
  (the offset in another effect's place, or read with a partner beside it that the log cannot size), and that reading
  within 15 % (needs the log diagnosed again: --logs DIR --diagnose BIN);
- IN_ITS_PLACE: the offset not named, another effect named in its place (or NOTHING_IN_ITS_PLACE);
- NAMED_BESIDE: an effect that was not hidden named beside the offset;
- ABSORBED: the offset named, a hidden partner not named (the offset read without it takes its part);
- RIGHT_SET_WITHIN_INTERVAL / RIGHT_SET_BEYOND_INTERVAL: the hidden set chosen, the offset off, the forced fit's
  interval holding its truth or not (the log's precision, or a bias / an interval too narrow).

Each miss also says whether the forced fit of the hidden effects read the offset within 15 % (the right model would
have sized it on this log). The water's density and the pitch trim are not counted as partners (the CTD's density is
flown, the trim read from the battery).

  classify_offset_misses.py D.json [--logs DIR --diagnose glider-diagnose --vehicles boards/vehicles]
"""
import argparse
import collections
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import diagnose_log, vehicle_file  # noqa: E402

EFFECT = 'buoyancy_offset'
NOT_PARTNERS = {'water_density', 'pitch_trim_offset'}
AMBIGUOUS_OTHER_SIDE = 'stated ambiguous, the offset right on the stated other side'
IN_ITS_PLACE = 'offset not named, another effect in its place'
NOTHING_IN_ITS_PLACE = 'offset not named, nothing in its place'
NAMED_BESIDE = 'an effect not hidden named beside it'
ABSORBED = 'a hidden partner not named, the offset absorbs it'
RIGHT_SET_WITHIN_INTERVAL = 'right set, off within the forced fit\'s interval (the log\'s precision)'
RIGHT_SET_BEYOND_INTERVAL = 'right set, off beyond the forced fit\'s interval'


def within(value, truth, fraction=0.15):
    return value is not None and abs(value - truth) <= fraction * abs(truth)


def judged_miss(draw):
    """True where the draw's offset is identifiable and not named within 15 %; None where not identifiable."""
    if not draw.get('ok') or EFFECT not in draw.get('truth', {}):
        return None
    measure = (draw.get('identifiability') or {}).get(EFFECT) or {}
    if not measure.get('identifiable'):
        return None
    reading = {f[0]: f[1] for f in draw['findings']}.get(EFFECT)
    return not within(reading, draw['truth'][EFFECT])


def classify(draw, other_side=None):
    """(cause, partners, forced fit within 15 %) of a judged miss. other_side: the offset's reading where the
    diagnosis stated it as an ambiguity's alternative (None where it did not or it is not known)."""
    truth = draw['truth'][EFFECT]
    named = {f[0]: f for f in draw['findings'] if f[0] not in NOT_PARTNERS}
    hidden = {e for e in draw['truth'] if e not in NOT_PARTNERS}
    measure = draw['identifiability'][EFFECT]
    forced_within = within(measure['value'], truth)
    extra = sorted(set(named) - hidden)
    unnamed = sorted(hidden - set(named))
    if other_side is not None and within(other_side, truth):
        return AMBIGUOUS_OTHER_SIDE, [], forced_within
    if EFFECT not in named:
        others = sorted(set(named))
        return (IN_ITS_PLACE if others else NOTHING_IN_ITS_PLACE), others, forced_within
    if extra:
        return NAMED_BESIDE, extra, forced_within
    if unnamed:
        return ABSORBED, unnamed, forced_within
    low, high = measure['ci95']
    held = low is not None and high is not None and low <= truth <= high
    return (RIGHT_SET_WITHIN_INTERVAL if held else RIGHT_SET_BEYOND_INTERVAL), [], forced_within


def other_side_of(draw, logs, diagnose, vehicles):
    """The offset's reading as a stated ambiguity's alternative, from the log diagnosed again (None if none)."""
    name = '%s_%d' % (draw['case'].replace('+', '-'), draw['seed'])
    log = os.path.join(logs, name + '.csv')
    return other_side_in(diagnose_log(diagnose, log, vehicle_file(vehicles, draw['variant']), timeout=None))


def other_side_in(report):
    """The offset's reading on a stated ambiguity's other side in a diagnosis JSON: the offset in another effect's
    place (its alternative_value), or the offset read with a partner beside it that the log cannot size (its
    value_beside); None where neither is stated."""
    for pair in report.get('ambiguous', []):
        if pair.get('alternative') == EFFECT and pair.get('reading', 'in its place') == 'in its place':
            return pair.get('alternative_value')
        if pair.get('effect') == EFFECT and pair.get('reading') == 'beside it':
            return pair.get('value_beside')
    return None


def tabulate(draws, other_side=lambda draw: None):
    """(lines, counts): one line per judged miss and counts[(cause, partners)] = [misses, forced fit within]."""
    lines, counts = [], collections.defaultdict(lambda: [0, 0])
    judged = missed = 0
    for draw in draws:
        miss = judged_miss(draw)
        if miss is None:
            continue
        judged += 1
        if not miss:
            continue
        missed += 1
        cause, partners, forced_within = classify(draw, other_side(draw))
        key = (cause, ','.join(partners))
        counts[key][0] += 1
        counts[key][1] += forced_within
        reading = {f[0]: f for f in draw['findings']}.get(EFFECT)
        lines.append('%s seed %d (%s): truth %.2f, read %s, forced fit %.2f: %s%s' % (
            draw['case'], draw['seed'], draw['variant'], draw['truth'][EFFECT],
            'none' if reading is None else '%.2f' % reading[1], draw['identifiability'][EFFECT]['value'], cause,
            ' (%s)' % ','.join(partners) if partners else ''))
    lines.append('identifiable %d, within 15 %% %d, missed %d' % (judged, judged - missed, missed))
    for (cause, partners), (n, forced) in sorted(counts.items(), key=lambda kv: -kv[1][0]):
        lines.append('%3d  %s%s; forced fit within 15 %% in %d' % (n, cause, ' (%s)' % partners if partners else '',
                                                                   forced))
    return lines, counts


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('details')
    p.add_argument('--logs', help='the run\'s --out DIR (kept with --keep): the stated ambiguity\'s other side')
    p.add_argument('--diagnose', help='the glider-diagnose that made the run')
    p.add_argument('--vehicles', default=os.path.join(os.path.dirname(__file__), '..', '..', 'boards', 'vehicles'))
    args = p.parse_args()
    with open(args.details) as f:
        draws = json.load(f)
    side = (lambda d: other_side_of(d, args.logs, args.diagnose, args.vehicles)) if args.logs and args.diagnose \
        else (lambda d: None)
    print('\n'.join(tabulate(draws, side)[0]))


if __name__ == '__main__':
    main()
