#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A lift change fitted on truth logs that hide none: how often the flight model reads a lift the truth does not have
(docs/science.md, "Why the lift change and the water's vertical velocity are seldom named": the margins keep such a
lift out, and a statement of an unnamed lift would say "seen" on it).

Each log of the independent truth simulator is flown with no hidden effect and the lift fitted beside the CTD's density
(`glider-diagnose --fit water_density,lift_change`, the identifiability measure's forced fit); printed per log: the
reading, its 95 % interval, and the truth's unmodelled terms (lift lag in chords, pitch-rate lift, skin-friction
Reynolds exponent); then how many read below 1 and how many intervals exclude 1, split by the truth's exponent
against the diagnosis's prior (0.1). A measurement, not a test: a fresh seed each run (printed; GLIDER_TEST_SEED=N
replays it).

  lift_on_clean_logs.py GLIDER_TRUTH GLIDER_DIAGNOSE VEHICLES_DIR WORKDIR [LOGS] [shallow|deep]
"""
import json
import os
import random
import statistics
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import diagnose_log, findings, fly, fresh_seed, vehicle_file  # noqa: E402


def excludes_one(row):
    return not row['low'] <= 1.0 <= row['high']


def main(truth, diagnose, vehicles, workdir, logs=30, variant='shallow'):
    seed = fresh_seed()
    print('seed %d (replay: GLIDER_TEST_SEED=%d), %s logs' % (seed, seed, variant))
    rng = random.Random(seed)
    os.makedirs(workdir, exist_ok=True)
    vehicle = vehicle_file(vehicles, variant)
    rows = []
    for _ in range(int(logs)):
        draw = rng.randrange(1, 2**62)
        log = os.path.join(workdir, 'clean_%d.csv' % draw)
        truth_file = log + '.truth.json'
        fly(truth, variant, draw, {}, log, truth_json=truth_file, yos=None, timeout=300)
        lift = findings(diagnose_log(diagnose, log, vehicle, ['--fit', 'water_density,lift_change'],
                                     timeout=300))['lift_change']
        with open(truth_file) as f:
            unmodelled = json.load(f)['unmodelled']
        row = {'lift': lift['value'], 'low': lift['ci95'][0], 'high': lift['ci95'][1],
               'lag': unmodelled['lift_lag_chords'], 'cl_q': unmodelled['cl_q'],
               'exponent': unmodelled['drag_reynolds_exponent']}
        rows.append(row)
        print('truth seed %d: lift %.3f [%.3f, %.3f]%s; lift lag %.2f chords, cl_q %.2f, Reynolds exponent %.3f' % (
            draw, row['lift'], row['low'], row['high'], ' excludes 1' if excludes_one(row) else '', row['lag'],
            row['cl_q'], row['exponent']))
        os.remove(log)
        os.remove(truth_file)
    print('median lift %.3f; below 1 in %d of %d; interval excludes 1 in %d' % (
        statistics.median(r['lift'] for r in rows), sum(r['lift'] < 1 for r in rows), len(rows),
        sum(excludes_one(r) for r in rows)))
    above = [r for r in rows if r['exponent'] > 0.12]
    print('truth exponent > 0.12: %d logs, %d exclude 1; <= 0.12: %d logs, %d exclude 1' % (
        len(above), sum(excludes_one(r) for r in above), len(rows) - len(above),
        sum(excludes_one(r) for r in rows) - sum(excludes_one(r) for r in above)))
    return 0


if __name__ == '__main__':
    sys.exit(main(*sys.argv[1:7]))
