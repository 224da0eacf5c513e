#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""misses.py on hand-made draws (no binary): per effect hidden / named / covered, and each miss's distance from the
truth in half-widths on the truth's side, each worked out by hand; the depth lag scored against the sensor's whole
lag (the benchmark's true_value); a failed draw left out; the printed lines from the command line."""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import misses  # noqa: E402


def draw(variant, truth, findings, ok=True, flight=None):
    return {'case': '+'.join(truth), 'seed': 7, 'variant': variant, 'ok': ok, 'truth': truth, 'findings': findings,
            'flight': flight or {}}


DRAWS = [
    # drag 1.30 read 1.21 [1.19, 1.23]: truth above, upper half-width 0.02, off 0.09 / 0.02 = 4.5
    draw('deep', {'drag_change': 1.30, 'lift_change': 1.30}, [['water_density', 1.0, None, None, False],
                                                            ['drag_change', 1.21, 1.19, 1.23, False]]),
    # lift 0.80 read 0.82 [0.70, 0.83]: truth below, lower half-width 0.12, off 0.02 / 0.12: covered
    draw('deep', {'lift_change': 0.80}, [['lift_change', 0.82, 0.70, 0.83, False]]),
    # depth lag hidden 1.0, the sensor's whole lag 1.3: read 1.0 [0.9, 1.2]: off 0.3 / 0.2 = 1.5 (not covered)
    draw('shallow', {'depth_lag': 1.0}, [['depth_lag', 1.0, 0.9, 1.2, False]], flight={'depth_sensor_lag_s': 1.3}),
    # failed: left out
    draw('deep', {'lift_change': 0.7}, [['lift_change', 0.9, 0.89, 0.91, False]], ok=False),
]


def main():
    failures = []
    rows, counts = misses.misses(DRAWS)
    if counts != {'drag_change': [1, 1, 0], 'lift_change': [2, 1, 1], 'depth_lag': [1, 1, 0]}:
        failures.append('counts %s' % counts)
    off = {r[0]: round(r[6], 6) for r in rows}
    if off != {'drag_change': 4.5, 'lift_change': round(0.02 / 0.12, 6), 'depth_lag': 1.5}:
        failures.append('half-widths off %s' % off)
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, 'details.json')
        with open(path, 'w') as f:
            json.dump(DRAWS, f)
        out = subprocess.run([sys.executable, os.path.join(HERE, 'misses.py'), path], capture_output=True, text=True)
        text = out.stdout
        if out.returncode != 0 or '| drag_change | 1 | 1 | 0 |' not in text or 'off 4.50 half-widths' not in text \
                or 'off 1.50 half-widths' not in text or 'off 0.17' in text:
            failures.append('printed:\n%s%s' % (text, out.stderr))
    for f in failures:
        print('FAIL', f)
    if failures:
        sys.exit(1)
    print('PASS misses counted and measured in half-widths as worked out by hand')


if __name__ == '__main__':
    main()
