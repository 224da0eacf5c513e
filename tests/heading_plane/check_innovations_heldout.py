#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The fin measured on the heading's innovations stands only where it also
predicts the held-out yos' innovations (docs/science.md, "the fin on the
innovations judged on the held-out yos").

Fixed draws of the independent truth (tools/science/truth), diagnosed as a
black box (`glider-diagnose --plane heading --json`), regression cases on
purpose:

- deep variant, the heading clean (a pump lag of 8.82 s and a depth lag of
  2.12 s hidden in the vertical plane): the fin's interval on the
  innovations excluded 1 - fin 1.585 [1.444, 1.727] and 1.119 [1.004,
  1.235] - while the held-out yos' innovations were worse with it (0.009277
  against 0.009186 rad, 0.002487 against 0.002446 rad). The code before
  named both fins. Now the vehicle link must name nothing.
- shallow variant, a fin x0.663 and x1.391 hidden: named before (0.703
  [0.659, 0.746], 1.385 [1.234, 1.536]; held-out innovations 13 % and 5 %
  better with the fin). The fin must still be named, its interval holding
  the truth, with no roll offset.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import VEHICLE_LINK, check, diagnose, finish  # noqa: E402

CLEAN_HEADING = ((1111553277215498003, {'pump_lag': 8.81808959}), (5771753172646025230, {'depth_lag': 2.11989784}))
HIDDEN_FIN = ((3210964722388215897, 0.663406891), (7946920725665275946, 1.39087312))


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    for seed, effects in CLEAN_HEADING:
        found = diagnose(truth, program, source, out, 'deep', seed, effects)
        named = sorted(e for e in found if e in VEHICLE_LINK)
        print('deep %d, %s hidden: heading findings %s' % (seed, effects, {
            k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']]) for k, v in found.items()}))
        if named:
            failures.append('a clean heading (deep %d) names %s' % (seed, ', '.join(named)))
    for seed, fin in HIDDEN_FIN:
        check(failures, diagnose(truth, program, source, out, 'shallow', seed, {'fin_effectiveness': fin}),
              'fin_effectiveness', fin, 'roll_offset')
    return finish(failures, 'innovations judged on the held-out yos')


if __name__ == '__main__':
    sys.exit(main())
