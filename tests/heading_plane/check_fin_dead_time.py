#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The vehicle link reads the fin between readings behind the servo's dead
time (docs/science.md, "The fin between readings behind the servo's dead
time").

Fixed draws of the independent truth (tools/science/truth), diagnosed as a
black box (`glider-diagnose --plane heading --json`), regression cases on
purpose. A command goes out at each reading and the servo moves the fin its
dead time later; the yaw model had the fin leave each reading at once, so
on a long dead time the fin it flew moved (dead time mod cycle) early, and
the yaw's delay took it:

- a fin delay of 10.61 s alone (deep, 6.8 s cycle: 3.8 s early): the code
  before named a yaw delay of 4.13 s [3, 6]; a fin delay of 11.08 s with a
  deadband (shallow, 4.1 s cycle: 2.9 s early): 2.94 s [1, 4]. The fin
  delay must be named, its interval holding the truth, and no yaw delay.
- a fin delay of 10.07 s beside a yaw delay of 3.22 s (deep): the code
  before read the yaw delay 4.74 s [3, 6], 47 % long; it must be named
  within 15 %, its interval holding the truth.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import check, diagnose, finish  # noqa: E402

FIN_DELAY_ALONE = (('deep', 5249423728465471654, {'fin_delay': 10.6107004}),
                   ('shallow', 6919368642615438176, {'fin_delay': 11.0770839, 'fin_deadband': 0.0227513712}))
PAIR = ('deep', 5343150856397987914, {'fin_delay': 10.0663813, 'yaw_delay': 3.22136662})


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    for variant, seed, effects in FIN_DELAY_ALONE:
        check(failures, diagnose(truth, program, source, out, variant, seed, effects), 'fin_delay',
              effects['fin_delay'], 'yaw_delay')
    variant, seed, effects = PAIR
    found = diagnose(truth, program, source, out, variant, seed, effects)
    check(failures, found, 'yaw_delay', effects['yaw_delay'], 'yaw_time_constant')
    f = found.get('yaw_delay')
    if f is not None and abs(f['value'] - effects['yaw_delay']) > 0.15 * effects['yaw_delay']:
        failures.append('yaw_delay %.3f read %.3f: not within 15 %%' % (effects['yaw_delay'], f['value']))
    return finish(failures, 'fin between readings behind the servo dead time')


if __name__ == '__main__':
    sys.exit(main())
