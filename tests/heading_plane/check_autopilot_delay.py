#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The autopilot's delay is named and sized; a clean log names none.

Fixed draws of the independent truth (tools/science/truth), diagnosed as a
black box (`glider-diagnose --plane heading --json`, check_fin_or_roll.py's
diagnose()):

- shallow variant, autopilot_delay 8.69 s alone: the truth's autopilot reads
  the heading late and the current command. The replay read the command
  late too, so every turn onto a new heading was a misfit no delay could
  explain: the code before named autopilot_dgain +15.7 [9.6, 21.8] and no
  delay. The delay must be named within 15 % of 8.69 s, its interval
  holding it and at least the grid's 0.5 s step wide, without a dgain.
- deep variant, clean: the law's timing (the truth's rate over its nominal
  cycle, its log thinned) reads as a delay of 0.2-0.7 s whose Jacobian
  interval excludes 0 within one grid step; the profile over the grid must
  keep it from being named.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import diagnose  # noqa: E402


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    delay = 8.68759
    found = diagnose(truth, program, source, out, 'shallow', 8605771638650690750, {'autopilot_delay': delay})
    print('autopilot_delay %.3f hidden: findings %s' % (delay, {
        k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']]) for k, v in found.items()}))
    f = found.get('autopilot_delay')
    if f is None:
        failures.append('autopilot_delay %.3f not named' % delay)
    else:
        low, high = f['ci95']
        if abs(f['value'] - delay) > 0.15 * delay:
            failures.append('autopilot_delay %.3f read %.3f' % (delay, f['value']))
        if not low <= delay <= high or high - low < 0.5:
            failures.append('autopilot_delay interval %s for %.3f' % (f['ci95'], delay))
    if 'autopilot_dgain' in found:
        failures.append('autopilot_dgain named beside a hidden autopilot_delay')
    clean = diagnose(truth, program, source, out, 'deep', 6535120216045304509, {})
    print('clean: findings %s' % {k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']])
                                  for k, v in clean.items()})
    if 'autopilot_delay' in clean:
        failures.append('a clean log names autopilot_delay')
    if failures:
        print('FAIL ' + '; '.join(failures))
        return 1
    print('PASS autopilot delay named and sized')
    return 0


if __name__ == '__main__':
    sys.exit(main())
