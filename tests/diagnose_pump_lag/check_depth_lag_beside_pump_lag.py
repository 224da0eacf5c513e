#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A depth lag fitted beside a named pump lag is named where the log sizes it.

Logs of the independent truth (tools/science/truth), fixed draws (6 yos),
diagnosed as a black box (`glider-diagnose --plane vertical --json`). The
selection names the pump lag; the depth lag is then fitted beside it
(read_pump_lag_beside_depth_lag) and named where its training interval puts
it at least the minimum detectable effect (1.96 + 1.645 sigmas) from no lag
(docs/science.md, "Method rule: a depth lag beside a named pump lag"). The
code before fitted it beside the pump lag and left it unnamed in both:

- deep, pump lag 24.20 s beside a 2.21 s depth lag (sensor lag 2.49 s; draw
  8029221135974058652 of benchmark seed 1845307681): depth lag 2.04 s in the
  extended vehicle's parameters, no finding.
- shallow, pump lag 13.86 s beside a 1.42 s depth lag (sensor lag 1.86 s;
  draw 3222373709780499529 of benchmark seed 648876647): 1.73 s, no finding.

Each draw must name both lags, the depth lag with an interval that holds the
truth's sensor lag (the hidden lag plus the sensor's own: what a diagnosis
reads, `flight.depth_sensor_lag_s`) and is not zero-width.
"""
import json
import os
import sys

from lag_checks import check_interval

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
from truth_draw import findings, fly_and_diagnose, vehicle_file  # noqa: E402

DRAWS = [('deep', 8029221135974058652, {'pump_lag': 24.1996002, 'depth_lag': 2.20586417}),
         ('shallow', 3222373709780499529, {'pump_lag': 13.8594998, 'depth_lag': 1.41867406})]


def main():
    truth, program, vehicles, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    for variant, seed, effects in DRAWS:
        name = 'depth_lag_beside'
        document = fly_and_diagnose(truth, program, vehicle_file(vehicles, variant), out, name, variant, seed,
                                    effects)
        with open(os.path.join(out, '%s_%d.json' % (name, seed))) as f:
            sensor = json.load(f)['flight']['depth_sensor_lag_s']
        found = findings(document)
        if 'pump_lag' not in found:
            failures.append('seed %d: the %.2f s pump lag not named' % (seed, effects['pump_lag']))
        lag = found.get('depth_lag')
        if lag is None:
            failures.append('seed %d: the %.2f s sensor lag not named (fitted beside the pump lag: %.2f s)' %
                            (seed, sensor, document['parameters']['depth_lag']))
            continue
        low, high = lag['ci95']
        print('seed %d (%s): depth lag %.2f s [%.2f, %.2f] (sensor lag %.2f s)' %
              (seed, variant, lag['value'], low, high, sensor))
        check_interval(failures, seed, low, high, sensor)
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS depth lag named beside the pump lag')
    return 0


if __name__ == '__main__':
    sys.exit(main())
