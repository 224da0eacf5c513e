#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The yaw's delay after the fin measured on the heading's innovations
(docs/science.md, "The yaw's delay on the innovations").

A fixed draw of the independent truth's deep variant, diagnosed as a black box
(`glider-diagnose --plane heading --json`, check_fin_or_roll.py's diagnose()):
a yaw delay of 7.2532 s alone. In the closed loop the rate error reads the
delay long (the fin answers the glider's random yaw), and the code before
named 8.63 s [7, 10] (8.30 s with the truth's random yaw switched off). On
the innovations it must be named within 15 % of the truth (the benchmark's
measure, benchmarks/diagnose_truth_coverage.py), its interval holding it,
and no fin.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import check, diagnose, finish  # noqa: E402


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    delay = 7.25320095
    found = diagnose(truth, program, source, out, 'deep', 2840067022836102147, {'yaw_delay': delay})
    check(failures, found, 'yaw_delay', delay, 'fin_effectiveness')
    if 'yaw_delay' in found and abs(found['yaw_delay']['value'] / delay - 1.0) > 0.15:
        failures.append('yaw_delay %.3f not within 15 %% of %.3f' % (found['yaw_delay']['value'], delay))
    return finish(failures, 'yaw delay measured on the innovations')


if __name__ == '__main__':
    sys.exit(main())
