#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The identifiability measure's stated limit in the heading plane
(benchmarks/identifiability.py ON_INNOVATIONS, issue 26 items 2-3): the fin's
authority and the yaw's lag are fitted but not judged - the forced
fit reads them on the rate error, which a closed loop biases, where the
diagnosis measures them on the heading's innovations.

A FIXED regression case, on purpose (the draw where the fin's reversal was
traced, coverage run seed 1887197222): the deep variant's truth seed
5553954220748243502 hiding a fin x1.948 and a yaw lag of 12.25 s. The forced
fit reads that fin 0.64 [0.14, 1.13] - the wrong side of 1; the diagnosis
names 1.82 - and the measure without the limit called it identifiable (z
3.8). Here both must be fitted (a value) and not judged. And a fresh-seed
draw (printed; GLIDER_TEST_SEED=N replays it) hiding a servo dead time of
the benchmark's sizes must still be judged (its forced fit is the
diagnosis's own estimator).

  check_heading_identifiability.py GLIDER_TRUTH GLIDER_DIAGNOSE BENCHMARKS_DIR VEHICLES_DIR WORKDIR
"""
import json
import os
import random
import sys

from check_ambiguity import fresh_seed

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import fly, vehicle_file  # noqa: E402

FIXED_SEED = 5553954220748243502
FIXED_EFFECTS = {'fin_effectiveness': 1.948219, 'yaw_time_constant': 12.2453675}


def measured(truth, diagnose, vehicles, workdir, seed, variant, effects):
    import diagnose_truth_coverage as coverage
    import identifiability
    log = os.path.join(workdir, f'heading_{seed}.csv')
    truth_path = log[:-4] + '.json'
    fly(truth, variant, seed, effects, log, truth_json=truth_path)
    with open(truth_path) as f:
        hidden = json.load(f)['effects']
    out = identifiability.measure(diagnose, log, vehicle_file(vehicles, variant), hidden, coverage.nominal,
                                  coverage.plane_of, timeout=120)
    for e, m in out.items():
        print(f"  {e} truth {hidden[e]:.4g}: forced fit {m['value']} {m['ci95']}, z {m['z']}, "
              f"identifiable {m['identifiable']} {m.get('not_judged', '')}")
    return out


def main(truth, diagnose, benchmarks, vehicles, workdir):
    sys.path.insert(0, benchmarks)
    import diagnose_truth_coverage as coverage
    os.makedirs(workdir, exist_ok=True)
    failed = False
    print(f'fixed regression draw {FIXED_SEED} (deep):')
    fixed = measured(truth, diagnose, vehicles, workdir, FIXED_SEED, 'deep', FIXED_EFFECTS)
    for e in FIXED_EFFECTS:
        if fixed[e]['value'] is None:
            print(f'FAIL: {e} was not fitted (the others\' sigmas are conditional on it)')
            failed = True
        if fixed[e]['identifiable'] is not None:
            print(f'FAIL: {e}, read on the rate error, was judged')
            failed = True
    seed = fresh_seed()
    rng = random.Random(seed)
    variant = rng.choice(('shallow', 'deep'))
    delay = coverage.SIZES['fin_delay'](rng)
    print(f'fresh draw: seed {seed} (replay: GLIDER_TEST_SEED={seed}), {variant}, fin_delay {delay:.3f} s:')
    fresh = measured(truth, diagnose, vehicles, workdir, seed, variant, {'fin_delay': delay})['fin_delay']
    if fresh['identifiable'] is None:
        print('FAIL: the servo\'s dead time, whose forced fit is the diagnosis\'s own, was not judged')
        failed = True
    if failed:
        return 1
    print('PASS heading identifiability judged where its forced fit is the diagnosis\'s estimator')
    return 0


if __name__ == '__main__':
    if len(sys.argv) != 6:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
