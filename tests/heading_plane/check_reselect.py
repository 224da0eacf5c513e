#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The fin-then-reselect rule's regressions (docs/science.md, "The
fin-then-reselect rule's regressions mended").

Two fixed draws of the independent truth, diagnosed as a black box
(`glider-diagnose --plane heading --json`, check_fin_or_roll.py's
diagnose()):

- shallow variant, roll offset 0.0245 rad alone: the fin measured alone on
  the innovations took the roll's steady yaw, and the code before named a
  fin 1.17 [1.01, 1.33] and no roll. The roll offset must be named, its
  interval holding the truth, and no fin.
- deep variant, clean: with a refuted fin no longer a candidate the
  reselection named a yaw time constant 21.8 s [15.5, 28.2]. The vehicle
  link must name nothing.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import check, check_clean, diagnose, finish  # noqa: E402


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    roll = 0.024542182
    check(failures, diagnose(truth, program, source, out, 'shallow', 706348478596914654, {'roll_offset': roll}),
          'roll_offset', roll, 'fin_effectiveness')
    clean = diagnose(truth, program, source, out, 'deep', 357883734764765648, {})
    check_clean(failures, clean)
    return finish(failures, 'reselection without the regressions')


if __name__ == '__main__':
    sys.exit(main())
