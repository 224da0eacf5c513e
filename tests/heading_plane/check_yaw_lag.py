#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The yaw's time constant measured on the heading's innovations, the roll read
as logged (docs/science.md, "The yaw's lag in a closed loop and the fin's
roll").

Two fixed draws of the independent truth's deep variant, diagnosed as a black
box (`glider-diagnose --plane heading --json`, check_fin_or_roll.py's
diagnose()):

- yaw time constant 12 s alone: in the closed loop the rate error reads the
  lag long (the glider's random yaw, which the fin answers), and the code
  before named 16.87 s [12.08, 21.67]. On the innovations it must be named
  with its interval holding 12 s, and no fin.
- clean: the code before named a fin 0.88 [0.79, 0.98] (the fin's roll turns
  the glider back against the fin; the yaw model held the glide's median
  roll). The vehicle link must name nothing.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import check, check_clean, diagnose, finish  # noqa: E402


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    lag = 12.0
    check(failures, diagnose(truth, program, source, out, 'deep', 2780611877, {'yaw_time_constant': lag}),
          'yaw_time_constant', lag, 'fin_effectiveness')
    clean = diagnose(truth, program, source, out, 'deep', 2275614738, {})
    check_clean(failures, clean)
    return finish(failures, 'yaw lag measured on the innovations')


if __name__ == '__main__':
    sys.exit(main())
