#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-diagnose reads an .sbd's fin as the file stored it.

A SIL flight of health's box mission with the fin's authority halved,
written as the firmware's decimated .sbd (tests/health/sbdlist.dat: m_fin,
c_fin, c_heading, m_heading stored on change, at most every 4 s), diagnosed
as a black box (`glider-diagnose FILE.sbd --plane heading --fit
fin_effectiveness --json`, the nominal vehicle). The commands must be held
between their stores and the fin rebuilt where the writer found it
unchanged (diagnose/stored_on_change.hpp), as health reads it: the fin's
95 % interval must hold 0.5. The code before read the .sbd raw: no row had a
heading command, and the heading plane was not diagnosed (exit 1).

A fresh seed each run (the SIL's noise and launch heading), printed;
GLIDER_TEST_SEED=<n> replays it.
"""
import json
import os
import random
import re
import shutil
import subprocess
import sys


def main():
    sil, program, source, out = sys.argv[1:5]
    seed = int(os.environ.get('GLIDER_TEST_SEED', random.SystemRandom().randrange(1, 2**31)))
    print('seed %d (GLIDER_TEST_SEED=%d replays it)' % (seed, seed))
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(os.path.join(out, 'files'))
    nominal = os.path.join(source, 'boards', 'vehicles', 'slocum_we01.toml')
    with open(nominal) as f:
        text = f.read()
    halved, n = re.subn(r'^fin_yaw_gain_per_m = ([0-9.]+)', lambda m: 'fin_yaw_gain_per_m = %.9g' %
                        (0.5 * float(m.group(1))), text, flags=re.M)
    if n != 1:
        print('FAIL no fin_yaw_gain_per_m in %s' % nominal)
        return 1
    flown = os.path.join(out, 'halved_fin.toml')
    with open(flown, 'w') as f:
        f.write(halved)
    subprocess.run([sil, '--vehicle', flown, '--mission',
                    os.path.join(source, 'tests', 'health', 'missions', 'health_box', 'missions', 'box.mi'),
                    '--slocum-dir', os.path.join(out, 'files'), '--sbdlist',
                    os.path.join(source, 'tests', 'health', 'sbdlist.dat'), '--seed', str(seed), '--heading-deg',
                    str(180 + seed % 21 - 10), '--quiet'], check=True, capture_output=True, timeout=120)
    sbd = sorted(f for f in os.listdir(os.path.join(out, 'files')) if f.endswith('.sbd'))[0]
    run = subprocess.run([program, os.path.join(out, 'files', sbd), '--vehicle', nominal, '--plane', 'heading',
                          '--fit', 'fin_effectiveness', '--json'], capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        print('FAIL glider-diagnose exit %d: %s' % (run.returncode, run.stderr[-300:]))
        return 1
    vehicle = ((json.loads(run.stdout).get('heading') or {}).get('links') or {}).get('vehicle') or {}
    fin = [f for f in vehicle.get('findings', []) or [] if f['effect'] == 'fin_effectiveness']
    if not fin:
        print('FAIL no fin_effectiveness fitted on %s' % sbd)
        return 1
    value, (low, high) = fin[0]['value'], fin[0]['ci95']
    print('%s: fin_effectiveness %.4f [%.4f, %.4f] for 0.5' % (sbd, value, low, high))
    if not low <= 0.5 <= high:
        print('FAIL the interval misses 0.5')
        return 1
    print('PASS fin read as stored on change')
    return 0


if __name__ == '__main__':
    sys.exit(main())
