#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""A stronger fin the rate error names nothing for is measured on the
innovations behind its screen (docs/science.md, "Why the heading plane's fin
is sized in half the draws").

Four fresh draws of the independent truth (tools/science/truth), deep
variant (the glider flies level, so no roll names the fin's measurement), a
fin effectiveness of x1.6-2.0 alone, each diagnosed as a black box
(`glider-diagnose --plane heading --json`, check_fin_or_roll.py's
diagnose()). In the closed loop the rate error reads a stronger fin weaker
(the fin answers the random yaw) and names nothing: the code before the
screen named 1 of 12 such draws (GLIDER_TEST_SEED 11, 12, 13), the screen 11
of 12. At least two of the four must name the fin, and none may name a roll
offset (the fin held at 1 by the reselection would read as one). From those
rates the test fails without the screen in ~96 % of runs and falsely with it
in ~0.2 % (binomial, 4 draws). The fin's interval is printed, not judged:
it held the truth in 8 of the 12 (docs/science.md's section).

A fresh seed each run, printed; GLIDER_TEST_SEED=<n> replays it.
"""
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import diagnose, finish  # noqa: E402
from truth_draw import fresh_seed  # noqa: E402 (check_fin_or_roll put tests/diagnose on the path)

DRAWS = 4
NEEDED = 2


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    seed = fresh_seed()
    print('seed %d (GLIDER_TEST_SEED=%d replays it)' % (seed, seed))
    rng = random.Random(seed)
    failures = []
    named = 0
    for _ in range(DRAWS):
        fin = rng.uniform(1.6, 2.0)
        draw = rng.randrange(1, 2**62)
        found = diagnose(truth, program, source, out, 'deep', draw, {'fin_effectiveness': fin})
        f = found.get('fin_effectiveness')
        named += f is not None
        print('fin %.4f hidden (truth seed %d): %s' % (fin, draw, {
            k: (round(v['value'], 4), [round(x, 4) for x in v['ci95']]) for k, v in found.items()}))
        if 'roll_offset' in found:
            failures.append('roll offset named beside a hidden fin %.4f (truth seed %d)' % (fin, draw))
    print('fin named: %d of %d' % (named, DRAWS))
    if named < NEEDED:
        failures.append('fin named in %d of %d draws (needed %d)' % (named, DRAWS, NEEDED))
    return finish(failures, 'stronger fin measured behind its screen')


if __name__ == '__main__':
    sys.exit(main())
