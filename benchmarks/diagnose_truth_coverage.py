#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Coverage of `glider-diagnose` on logs of the independent truth simulator.

Every effect of the vertical and heading vocabularies, hidden singly and in
pairs at realistic sizes (small ones included) in logs flown by
`glider-truth` (tools/science/truth: its own equations, integrator,
controllers, sensors and water - never the project's model), each log
diagnosed by `glider-diagnose --json` as a black box. Fresh random seeds
every run: the run's seed is printed, `--seed S` replays the whole run and
`--draw-seed D --cases CASE --draws 1` one draw. No seed list is committed.

Per case: named (the hidden effect among the findings), within 15 % (of the
effect's size: truth - nominal, the nominal being 1 for a ratio, the log's
stated autopilot gains, the vehicle file's yaw time constant, else 0), 95 %
coverage (the interval holds the truth, among the named), spurious findings
(draws with a finding of an effect not hidden; the measured water density is
an input, not a finding), ambiguous (draws where the diagnosis says the
hidden effect cannot be told apart from another: a finding's "ambiguous" or
"alternatives", a vertical "ambiguous" pair or a heading link's "ambiguous"
verdict), and for clean logs how many give no finding at all.

With --identifiability, each hidden effect is also judged identifiable or
not on its log by a measure that does not use the diagnosis's choice
(benchmarks/identifiability.py: a forced joint fit of the hidden effects, the
truth's size over the fit's standard error, z >= 3.6), and the per-effect
table is split by it beside the unsplit figures.
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import random
import secrets
import statistics
import subprocess
import sys
import tempfile
import time

import identifiability

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'tests', 'diagnose'))
from truth_draw import run_truth, vehicle_file  # noqa: E402  (the tests' one way to fly the truth)

VERTICAL = ['buoyancy_offset', 'drag_change', 'hull_compressibility', 'thermal_expansion', 'vertical_water_velocity',
            'pitch_trim_offset', 'pump_lag', 'lift_change', 'depth_lag']
HEADING = ['fin_delay', 'fin_deadband', 'yaw_delay', 'fin_effectiveness', 'roll_offset', 'yaw_time_constant',
           'autopilot_gain', 'autopilot_integral', 'autopilot_dgain', 'autopilot_delay', 'autopilot_deadband']
# Pairs: the near-degenerate ones of issue 26 and one of each plane with the other.
PAIRS = ['buoyancy_offset+vertical_water_velocity', 'buoyancy_offset+drag_change', 'drag_change+pump_lag',
         'buoyancy_offset+hull_compressibility', 'thermal_expansion+hull_compressibility', 'pump_lag+depth_lag',
         'lift_change+drag_change', 'pitch_trim_offset+buoyancy_offset', 'fin_delay+fin_deadband',
         'fin_delay+yaw_delay', 'fin_effectiveness+yaw_time_constant', 'autopilot_gain+autopilot_delay',
         'drag_change+fin_delay', 'buoyancy_offset+roll_offset']
# The autopilot the truth's logs state, and the vehicle files' heading nominal.
STATED = {'autopilot_gain': 1.5, 'autopilot_integral': 0.02, 'autopilot_dgain': -4.0, 'yaw_time_constant': 2.0}
RATIOS = {'drag_change', 'lift_change', 'fin_effectiveness'}
INPUTS = {'water_density'}  # measured inputs, not claims


def either(rng, a, b):
    return rng.uniform(*a) if rng.random() < 0.5 else rng.uniform(*b)


def sign(rng):
    return -1.0 if rng.random() < 0.5 else 1.0


# Realistic sizes, small ones included (units of the vocabulary).
SIZES = {
    'buoyancy_offset': lambda r: sign(r) * r.uniform(10, 80),
    'drag_change': lambda r: r.uniform(1.08, 1.5),
    'hull_compressibility': lambda r: r.uniform(0.5e-10, 3e-10),
    'thermal_expansion': lambda r: r.uniform(1e-5, 7e-5),
    'vertical_water_velocity': lambda r: sign(r) * r.uniform(0.005, 0.03),
    'pitch_trim_offset': lambda r: sign(r) * r.uniform(0.03, 0.15),
    'pump_lag': lambda r: r.uniform(3.0, 30.0),
    'lift_change': lambda r: either(r, (0.7, 0.9), (1.1, 1.5)),
    'depth_lag': lambda r: r.uniform(0.5, 4.0),
    'fin_delay': lambda r: r.uniform(1.0, 12.0),
    'fin_deadband': lambda r: r.uniform(0.01, 0.06),
    'yaw_delay': lambda r: r.uniform(1.0, 8.0),
    'fin_effectiveness': lambda r: either(r, (0.5, 0.8), (1.25, 2.0)),
    'roll_offset': lambda r: sign(r) * r.uniform(0.02, 0.1),
    'yaw_time_constant': lambda r: r.uniform(4.0, 15.0),
    'autopilot_gain': lambda r: either(r, (0.5, 1.2), (1.8, 3.0)),
    'autopilot_integral': lambda r: either(r, (0.0, 0.01), (0.03, 0.06)),
    'autopilot_dgain': lambda r: either(r, (-10.0, -6.0), (-2.0, 0.0)),
    'autopilot_delay': lambda r: r.uniform(2.0, 10.0),
    'autopilot_deadband': lambda r: r.uniform(0.02, 0.1),
}


def nominal(effect):
    if effect in RATIOS:
        return 1.0
    return STATED.get(effect, 0.0)


def cases_of_plane(plane):
    """The default cases: every case, or one plane's (clean logs, its singles, the pairs inside it)."""
    if plane == 'both':
        return ['none'] + VERTICAL + HEADING + PAIRS
    own = VERTICAL if plane == 'vertical' else HEADING
    return ['none'] + own + [c for c in PAIRS if all(e in own for e in c.split('+'))]


def draw_seed(base, case, i):
    digest = hashlib.sha256(('%d/%s/%d' % (base, case, i)).encode()).digest()
    return int.from_bytes(digest[:8], 'little') >> 1


def findings_of(diagnosis):
    """(effect, value, low, high, finding) of both planes."""
    out = []
    for f in diagnosis.get('findings', []) or []:
        ci = f.get('ci95') if f.get('fitted', True) else None  # a measured input has no interval
        ci = ci or [None, None]
        out.append((f['effect'], f.get('value'), ci[0], ci[1], f))
    heading = diagnosis.get('heading') or {}
    for link in (heading.get('links') or {}).values():
        for f in link.get('findings', []) or []:
            ci = f.get('ci95') or [None, None]
            out.append((f['effect'], f.get('value'), ci[0], ci[1], f))
    return out


def run_draw(args, case, seed):
    rng = random.Random(seed)
    effects = {e: SIZES[e](rng) for e in case.split('+') if e != 'none'}
    variant = 'deep' if rng.random() < 0.5 else 'shallow'
    vehicle = vehicle_file(os.path.join(args.source, 'boards', 'vehicles'), variant)
    name = '%s_%d' % (case.replace('+', '-'), seed)
    log = os.path.join(args.out, name + '.csv')
    truth_path = os.path.join(args.out, name + '.json')
    result = {'case': case, 'seed': seed, 'variant': variant, 'ok': False}
    start = time.monotonic()
    made = run_truth(args.truth, variant, seed, effects, log, truth_json=truth_path, yos=args.yos,
                     timeout=args.timeout)
    result['truth_s'] = time.monotonic() - start
    if made.returncode != 0:
        result['error'] = 'glider-truth: ' + (made.stderr.strip() or made.stdout.strip())[-300:]
        return result
    with open(truth_path) as f:
        truth = json.load(f)
    result['truth'] = truth['effects']
    result['flight'] = truth['flight']
    start = time.monotonic()
    try:
        plane = [] if args.plane == 'both' else ['--plane', args.plane]
        diagnosed = subprocess.run([args.diagnose, log, '--vehicle', vehicle, '--json'] + plane + args.diagnose_arg,
                                   capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        result['error'] = 'glider-diagnose: timed out after %d s' % args.timeout
        return result
    result['diagnose_s'] = time.monotonic() - start
    if diagnosed.returncode != 0:
        result['error'] = 'glider-diagnose exit %d: %s' % (diagnosed.returncode, diagnosed.stderr.strip()[-300:])
        return result
    document = json.loads(diagnosed.stdout)
    # glider-diagnose states ambiguity at the top level ("ambiguous": the pairs the held-out yos cannot tell
    # apart, vertical plane); a finding is ambiguous when it is one side of such a pair.
    paired = {side for a in document.get('ambiguous', []) for side in (a.get('effect'), a.get('alternative'))}
    # The heading plane states its pairs per link (verdict "ambiguous").
    for link in ((document.get('heading') or {}).get('links') or {}).values():
        paired |= {side for a in link.get('identifiability', []) or [] if a.get('verdict') == 'ambiguous'
                   for side in (a.get('chosen'), a.get('alternative'))}
    result['stated_ambiguous'] = sorted(paired)
    # The pairs themselves, so a finding stated beside the hidden effect can be told from one stated beside another.
    pairs = [[a.get('effect'), a.get('alternative')] for a in document.get('ambiguous', [])]
    for link in ((document.get('heading') or {}).get('links') or {}).values():
        pairs += [[a.get('chosen'), a.get('alternative')] for a in link.get('identifiability', []) or []
                  if a.get('verdict') == 'ambiguous']
    result['ambiguous_pairs'] = pairs
    result['findings'] = [(e, v, lo, hi, bool(f.get('ambiguous') or f.get('alternatives') or e in paired))
                          for e, v, lo, hi, f in findings_of(document)]
    if args.identifiability:
        start = time.monotonic()
        try:
            result['identifiability'] = identifiability.measure(
                args.diagnose, log, vehicle, {e: true_value(result, e, v) for e, v in result['truth'].items()},
                nominal, plane_of, args.timeout,
                rivals if args.identifiability == 'rivals' else None)
        except (RuntimeError, subprocess.TimeoutExpired, ValueError) as error:
            result['identifiability_error'] = str(error)
        result['identifiability_s'] = time.monotonic() - start
    result['ok'] = True
    if not args.keep:
        os.remove(log)
        os.remove(truth_path)
    return result


def true_value(r, effect, hidden):
    """What a finding of the effect measures. glider-truth's depth sensor has its own lag (0.1-0.5 s, drawn per log)
    and a hidden depth lag is added to it; the sum is the sensor's lag, `flight.depth_sensor_lag_s`, and that is what
    the diagnosis reads (the clean logs' own lag alone is too small to be named). Every other effect is its hidden
    value."""
    if effect == 'depth_lag':
        return (r.get('flight') or {}).get('depth_sensor_lag_s', hidden)
    return hidden


def score(r):
    """Per hidden effect: named, within 15 %, covered (None: no interval); and the draw's spurious findings."""
    per = {}
    found = {e: (v, lo, hi, amb) for e, v, lo, hi, amb in r['findings']}
    for effect, truth in r['truth'].items():
        truth = true_value(r, effect, truth)
        if effect not in found:
            per[effect] = (False, False, None, False)
            continue
        v, lo, hi, amb = found[effect]
        size = abs(truth - nominal(effect))
        within = v is not None and size > 0 and abs(v - truth) <= 0.15 * size
        covered = None if lo is None or hi is None else lo <= truth <= hi
        per[effect] = (True, within, covered, amb)
    spurious = [e for e, *_ in r['findings'] if e not in r['truth'] and e not in INPUTS]
    ambiguous = any(amb for *_, amb in r['findings'])
    return per, spurious, ambiguous


# A rival fitted in one plane that stands for an effect of the other: the heading plane's lift factor is the
# vertical plane's lift change as the roll's turn reads it (docs/science.md "A roll offset or the wings' lift").
STANDS_FOR = {'lift_factor': 'lift_change'}


def stated_beside_hidden(r, spurious):
    """The spurious findings stated ambiguous with a hidden effect (the pair's other side is hidden, directly or
    through STANDS_FOR): the log could not tell them apart and the diagnosis said so, with both readings. Still
    counted as spurious in the tables' spurious columns; this is the part of them that was stated. Runs saved
    before the pairs were recorded have none."""
    hidden = set(r['truth'])
    stated = set()
    for a, b in r.get('ambiguous_pairs') or []:
        for finding, other in ((a, b), (b, a)):
            if finding in spurious and STANDS_FOR.get(other, other) in hidden:
                stated.add(finding)
    return sorted(stated)


def plane_of(effect):
    return 'heading' if effect in HEADING else 'vertical'


def rivals(effect):
    """The other candidates of an effect's plane (identifiability.py's stricter reading)."""
    return [e for e in (HEADING if effect in HEADING else VERTICAL) if e != effect]


def pct(a, b):
    return '-' if b == 0 else '%d/%d (%.0f %%)' % (a, b, 100.0 * a / b)


def table(results, cases):
    lines = ['| case | draws | named | within 15 % | 95 % coverage | spurious (draws) | spurious vertical | '
             'spurious heading | ambiguous | no finding |',
             '|---|---|---|---|---|---|---|---|---|---|']
    for case in cases:
        rs = [r for r in results if r['case'] == case]
        ok = [r for r in rs if r['ok']]
        named = within = covered = valued = spur = spur_v = spur_h = amb = clean = slots = 0
        for r in ok:
            per, spurious, ambiguous = score(r)
            for n, w, c, _ in per.values():
                slots += 1
                named += n
                within += w
                if c is not None:
                    valued += 1
                    covered += c
            spur += bool(spurious)
            spur_v += any(plane_of(e) == 'vertical' for e in spurious)
            spur_h += any(plane_of(e) == 'heading' for e in spurious)
            amb += ambiguous
            clean += not [f for f in r['findings'] if f[0] not in INPUTS]
        failed = len(rs) - len(ok)
        lines.append('| %s | %d%s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
            case, len(rs), ' (%d failed)' % failed if failed else '', pct(named, slots) if case != 'none' else '-',
            pct(within, slots) if case != 'none' else '-', pct(covered, valued) if case != 'none' else '-',
            pct(spur, len(ok)), pct(spur_v, len(ok)), pct(spur_h, len(ok)), pct(amb, len(ok)),
            pct(clean, len(ok)) if case == 'none' else '-'))
    lines += ['', '| variant | draws | hidden effects named | within 15 % | 95 % coverage | spurious vertical | '
              'spurious heading | spurious, not stated ambiguous with a hidden effect: vertical / heading | '
              'clean logs with no finding |', '|---|---|---|---|---|---|---|---|---|']
    for variant in ('shallow', 'deep'):
        ok = [r for r in results if r['ok'] and r.get('variant') == variant]
        slots = named = within = covered = valued = spur_v = spur_h = bare_v = bare_h = 0
        for r in ok:
            per, spurious, _ = score(r)
            for n, w, c, _ in per.values():
                slots += 1
                named += n
                within += w
                valued += c is not None
                covered += bool(c)
            spur_v += any(plane_of(e) == 'vertical' for e in spurious)
            spur_h += any(plane_of(e) == 'heading' for e in spurious)
            bare = set(spurious) - set(stated_beside_hidden(r, spurious))
            bare_v += any(plane_of(e) == 'vertical' for e in bare)
            bare_h += any(plane_of(e) == 'heading' for e in bare)
        clean = [r for r in ok if r['case'] == 'none']
        empty = sum(1 for r in clean if not [f for f in r['findings'] if f[0] not in INPUTS])
        lines.append('| %s | %d | %s | %s | %s | %s | %s | %s / %s | %s |' % (
            variant, len(ok), pct(named, slots), pct(within, slots), pct(covered, valued), pct(spur_v, len(ok)),
            pct(spur_h, len(ok)), pct(bare_v, len(ok)), pct(bare_h, len(ok)), pct(empty, len(clean))))
    return '\n'.join(lines + [''] + effect_table(results))


def tally(slots):
    """hidden, named, within 15 %, covered of those with an interval (a/b), ambiguous stated."""
    valued = [s for s in slots if s['covered'] is not None]
    return (len(slots), sum(s['named'] for s in slots), sum(s['within'] for s in slots),
            pct(sum(s['covered'] for s in valued), len(valued)), sum(s['ambiguous'] for s in slots))


def effect_table(results):
    """Per effect (singles and pairs): the unsplit figures, the stated ambiguity and, where measured, the split by
    identifiability (benchmarks/identifiability.py)."""
    slots = {}
    measured = any('identifiability' in r for r in results if r['ok'])
    strict = any('z_rival' in m for r in results if r['ok'] for m in r.get('identifiability', {}).values())
    for r in results:
        if not r['ok']:
            continue
        per, _, _ = score(r)
        stated = set(r.get('stated_ambiguous', []))
        judged = r.get('identifiability', {})
        for effect, (n, w, c, amb) in per.items():
            m = judged.get(effect, {})
            slots.setdefault(effect, []).append({'named': n, 'within': w, 'covered': c,
                                                 'ambiguous': bool(amb or effect in stated),
                                                 'identifiable': m.get('identifiable'), 'sizeable': m.get('sizeable'),
                                                 'z': m.get('z'), 'rival': m.get('identifiable_rival')})
    head = '| effect (singles and pairs) | hidden | named | within 15 % | 95 % coverage | ambiguous stated |'
    rule = '|---|---|---|---|---|---|'
    if measured:
        head += (' identifiable (z >= %.1f) | named | within 15 %% | 95 %% coverage | ambiguous stated |'
                 ' not identifiable: named | within 15 %% | not judged | sizeable (z >= %.1f): within 15 %% |'
                 ' median z |' % (identifiability.Z_IDENTIFIABLE, identifiability.Z_SIZEABLE))
        rule += '---|---|---|---|---|---|---|---|---|---|'
    if strict:
        head += ' identifiable against its nearest rival | named | within 15 % | 95 % coverage |'
        rule += '---|---|---|---|'
    lines = [head, rule]
    for effect in VERTICAL + HEADING:
        if effect not in slots:
            continue
        h, n, w, cov, amb = tally(slots[effect])
        line = '| %s | %d | %s | %s | %s | %s |' % (effect, h, pct(n, h), pct(w, h), cov, pct(amb, h))
        if measured:
            yes = [s for s in slots[effect] if s['identifiable'] is True]
            no = [s for s in slots[effect] if s['identifiable'] is False]
            big = [s for s in slots[effect] if s['sizeable'] is True]
            zs = [s['z'] for s in slots[effect] if s['z'] is not None]
            hy, ny, wy, covy, ay = tally(yes)
            hn, nn, wn, _, _ = tally(no)
            line += ' %s | %s | %s | %s | %s | %s | %s | %d | %s | %s |' % (
                pct(hy, h), pct(ny, hy), pct(wy, hy), covy, pct(ay, hy), pct(nn, hn), pct(wn, hn),
                h - hy - hn, pct(sum(s['within'] for s in big), len(big)),
                '%.1f' % statistics.median(zs) if zs else '-')
        if strict:
            hr, nr, wr, covr, _ = tally([s for s in slots[effect] if s['rival'] is True])
            line += ' %s | %s | %s | %s |' % (pct(hr, h), pct(nr, hr), pct(wr, hr), covr)
        lines.append(line)
    return lines


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('--draws', type=int, default=5, help='draws per case')
    p.add_argument('--jobs', type=int, default=2, help='draws at once')
    p.add_argument('--seed', type=int, help='the run\'s seed (default: fresh from the OS, printed)')
    p.add_argument('--draw-seed', type=int, help='replay exactly this draw (with --cases CASE --draws 1)')
    p.add_argument('--cases', help='comma list: effect ids, a+b pairs, none (default: none, every single, the pairs)')
    p.add_argument('--yos', type=int, default=6, help='yos per truth log')
    p.add_argument('--plane', choices=('both', 'vertical', 'heading'), default='both',
                   help='diagnose this plane only (and by default its cases only: the clean logs, its singles '
                   'and the pairs inside it)')
    p.add_argument('--build', default=os.environ.get('GLIDER_BUILD_DIR', 'build/release'))
    p.add_argument('--truth', help='glider-truth (default: BUILD/tools/science/truth/glider-truth)')
    p.add_argument('--diagnose', help='glider-diagnose (default: BUILD/tools/science/diagnose/glider-diagnose)')
    p.add_argument('--diagnose-arg', action='append', default=[],
                   help='one more argument for every glider-diagnose run (repeat; e.g. --diagnose-arg=--score-block '
                        '--diagnose-arg=60): a method switch benchmarked paired on the same seed')
    p.add_argument('--source', default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    p.add_argument('--out', help='directory for the logs (default: a temporary one)')
    p.add_argument('--keep', action='store_true', help='keep the logs and truths')
    p.add_argument('--timeout', type=int, default=600, help='seconds per program run')
    p.add_argument('--details', help='JSON file: every draw with its truth and findings')
    p.add_argument('--from-details', help='tabulate a run saved with --details again (nothing is flown)')
    p.add_argument('--identifiability', nargs='?', const='fit', choices=('fit', 'rivals'),
                   help='also judge each hidden effect identifiable or not on its log (one forced fit of the '
                        'hidden effects per draw; "rivals": also once more with each other candidate of its plane '
                        'added; benchmarks/identifiability.py) and split the per-effect table')
    args = p.parse_args()
    if args.from_details:
        with open(args.from_details) as f:
            results = json.load(f)
        cases = list(dict.fromkeys(r['case'] for r in results))
        print(table(results, cases))
        return 0
    args.truth = args.truth or os.path.join(args.build, 'tools', 'science', 'truth', 'glider-truth')
    args.diagnose = args.diagnose or os.path.join(args.build, 'tools', 'science', 'diagnose', 'glider-diagnose')
    for program in (args.truth, args.diagnose):
        if not os.access(program, os.X_OK):
            print('diagnose_truth_coverage: %s is not built' % program, file=sys.stderr)
            return 1
    cases = args.cases.split(',') if args.cases else cases_of_plane(args.plane)
    for case in cases:
        for e in case.split('+'):
            if e != 'none' and e not in SIZES:
                print('diagnose_truth_coverage: unknown effect %r in case %r' % (e, case), file=sys.stderr)
                return 2
    base = args.seed if args.seed is not None else secrets.randbits(31)
    tmp = None
    if not args.out:
        tmp = tempfile.TemporaryDirectory(prefix='glider_truth_coverage_')
        args.out = tmp.name
    os.makedirs(args.out, exist_ok=True)
    work = [(c, args.draw_seed if args.draw_seed is not None else draw_seed(base, c, i))
            for c in cases for i in range(args.draws)]
    print('run seed %d (%d cases x %d draws = %d logs, %d jobs)%s' % (
        base, len(cases), args.draws, len(work), args.jobs,
        '; draw seed %d' % args.draw_seed if args.draw_seed is not None else ''), flush=True)
    start = time.monotonic()
    results = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(run_draw, args, c, s) for c, s in work]
        for k, f in enumerate(concurrent.futures.as_completed(futures), 1):
            try:
                results.append(f.result())
            except Exception as error:  # a program that hung past its timeout
                results.append({'case': '?', 'seed': 0, 'ok': False, 'error': str(error)})
            print('\r%d of %d draws' % (k, len(work)), end='', file=sys.stderr, flush=True)
    print('', file=sys.stderr)
    print(table(results, cases))
    failures = [r for r in results if not r['ok']]
    for r in failures[:10]:
        print('  failed: %s seed %d: %s' % (r['case'], r['seed'], r.get('error', '')))
    misses = []
    for r in results:
        if not r['ok']:
            continue
        per, spurious, _ = score(r)
        lost = [e for e, (n, w, c, a) in per.items() if not w]
        claims = [f for f in r['findings'] if f[0] not in INPUTS]  # the CTD's density is an input, not a finding
        if lost or spurious or (r['case'] == 'none' and claims):
            misses.append('  %s seed %d (%s, %s, %.1f s cycle): findings %s' % (
                r['case'], r['seed'], r['variant'], r['flight']['pitch_control'], r['flight']['cycle_s'],
                ', '.join('%s %.4g [%.4g, %.4g]' % (e, v, lo if lo is not None else float('nan'),
                                                   hi if hi is not None else float('nan'))
                          for e, v, lo, hi, _ in claims) or 'none'))
    if misses:
        print('draws not named within 15 %, with spurious findings or not clean (replay: --draw-seed SEED --cases CASE '
              '--draws 1):')
        print('\n'.join(misses[:60]))
    truth_s = [r['truth_s'] for r in results if 'truth_s' in r]
    diag_s = [r['diagnose_s'] for r in results if 'diagnose_s' in r]
    rows = [r['flight']['log_rows'] for r in results if 'flight' in r]
    ident_s = [r['identifiability_s'] for r in results if 'identifiability_s' in r]
    if ident_s:
        print('identifiability (%s): %.1f s median per draw (%.1f-%.1f); not judged: %d draws with a failed '
              'forced fit' % (args.identifiability, statistics.median(ident_s), min(ident_s), max(ident_s),
                              sum('identifiability_error' in r for r in results)))
    if truth_s:
        print('speed: one truth log %.2f s median (%.2f-%.2f, %d rows median); one diagnosis %.1f s median '
              '(%.1f-%.1f); %d draws in %.0f s wall with %d jobs' % (
                  statistics.median(truth_s), min(truth_s), max(truth_s), statistics.median(rows) if rows else 0,
                  statistics.median(diag_s) if diag_s else float('nan'), min(diag_s) if diag_s else float('nan'),
                  max(diag_s) if diag_s else float('nan'), len(results), time.monotonic() - start, args.jobs))
    print('replay this run: %s --seed %d --draws %d%s' % (
        'benchmarks/diagnose_truth_coverage.py', base, args.draws, ' --cases ' + ','.join(cases) if args.cases else ''))
    if args.details:
        with open(args.details, 'w') as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == '__main__':
    sys.exit(main())
