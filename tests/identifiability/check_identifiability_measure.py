#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The coverage benchmark's identifiability measure (benchmarks/identifiability.py,
issue 26 items 2-3) on two truth logs of the same fresh seed and variant that
differ only in the size of a hidden thermal expansion: 3e-4 /K must be judged
identifiable (z >= 3.6), its forced fit within 25 % of the truth, and 2e-6 /K
must be judged and not identifiable. Design draws (12 logs, 6 fresh seeds,
both variants): z 8.6-71 and 0-18 % off for 3e-4, z 0.10-0.48 for 2e-6.
Fails where the measure gives no verdict or the wrong one, or reads the large
effect elsewhere (the forced fit without the CTD's density read it 20-60 %
low on 4 of 4 seeds).

A fresh seed every run (printed; GLIDER_TEST_SEED=N replays it).

  check_identifiability_measure.py GLIDER_TRUTH GLIDER_DIAGNOSE BENCHMARKS_DIR VEHICLES_DIR WORKDIR
"""
import json
import os
import random
import sys

from check_ambiguity import fresh_seed

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import run_truth, vehicle_file  # noqa: E402


def main(truth, diagnose, benchmarks, vehicles, workdir):
    sys.path.insert(0, benchmarks)
    import diagnose_truth_coverage as coverage
    import identifiability
    seed = fresh_seed()
    print(f'seed {seed} (replay: GLIDER_TEST_SEED={seed})')
    os.makedirs(workdir, exist_ok=True)

    def make(seed, variant, size):
        log = os.path.join(workdir, f'thermal_{size:g}_{seed}.csv')
        made = run_truth(truth, variant, seed, {'thermal_expansion': size}, log, truth_json=log[:-4] + '.json')
        return log, made

    # The large expansion (10x a real hull's) makes some draws' warm surface
    # water lift the truth's vehicle out of it (1 seed seen in 30+; glider-truth
    # refuses it: "the vehicle left the water"). That draw is no case of the
    # measure: another seed, derived from this one (so the replay is the same),
    # at most 3 times.
    for attempt in range(3):
        variant = random.Random(seed).choice(('shallow', 'deep'))
        _, made = make(seed, variant, 3e-4)
        if made.returncode == 0 or 'left the water' not in made.stderr:
            break
        print(f'glider-truth cannot fly seed {seed} ({variant}) with 3e-4 /K: {made.stderr.strip()[-120:]}; '
              'drawing another')
        seed = random.Random(seed).randrange(1, 2**31)
    vehicle = vehicle_file(vehicles, variant)
    print(f'draw seed {seed}, {variant} variant')
    failed = False
    for size, expected in ((3e-4, True), (2e-6, False)):
        log, made = make(seed, variant, size)
        truth_path = log[:-4] + '.json'
        if made.returncode != 0:
            print('FAIL: glider-truth:', made.stderr.strip()[-300:])
            return 1
        with open(truth_path) as f:
            effects = json.load(f)['effects']
        m = identifiability.measure(diagnose, log, vehicle, effects, coverage.nominal, coverage.plane_of,
                                    timeout=120)['thermal_expansion']
        print(f"thermal_expansion {size:g} /K: forced fit {m['value']} {m['ci95']}, z {m['z']} -> "
              f"identifiable {m['identifiable']} (expected {expected})")
        if m['identifiable'] is not expected:
            print('FAIL: the measure judged this size wrongly (or not at all)')
            failed = True
        if expected and not (m['value'] is not None and abs(m['value'] - size) <= 0.25 * size):
            print('FAIL: the forced fit reads the large effect more than 25 % off its truth')
            failed = True
    if failed:
        return 1
    print('PASS identifiability measured')
    return 0


if __name__ == '__main__':
    if len(sys.argv) != 6:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(main(*sys.argv[1:]))
