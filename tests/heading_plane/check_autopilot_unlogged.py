#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The autopilot replay steps the law at every cycle, logged or not
(docs/science.md, "The autopilot replay's unlogged dive start, and the
truth's nominal cycle").

Fixed draws of the independent truth (tools/science/truth), diagnosed as a
black box (`glider-diagnose --plane heading --json`), regression cases on
purpose. The truth does not log 2 % of its cycles; the replay stepped the
law once over such a gap, so in a turn (the error a radian, the fin at its
limit) its integrator took the later error for the whole gap, and from the
fin's leaving its limit on missed the logged c_fin by a few hundredths of a
radian, which an autopilot delay, integral or dgain took:

- clean-heading draws (5-7 s cycles): the code before named an autopilot
  delay of 1.04 s (shallow, drag x1.50), of 1.64 s and an integral (deep,
  pump lag 27 s), of 1.27 s and an integral (shallow, fin x1.40). The
  autopilot link must name nothing.
- hidden autopilot gains x0.974 (shallow) and 2.151 (deep): the code
  before named an integral and a delay beside the first, an integral and a
  dgain in place of the second. The gain must be named within 15 %, its
  interval holding the truth, and nothing else on the autopilot link.
- clean-heading draws where the unlogged cycle is the one a dive started
  at, the new heading set (session hdap2): stepped on the earlier command,
  the integrator lost ki x 1.3 rad x the cycle there; the replay named an
  integral and a gain (drag x1.34 + pump lag 11 s) and a delay of 1.54 s
  (pitch trim offset). The unlogged cycle takes the new command once the
  interpolated depth has passed the depth the log's other command changes
  happened at; the autopilot link must name nothing.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_fin_or_roll import check, diagnose, finish  # noqa: E402

AUTOPILOT_LINK = {'autopilot_gain', 'autopilot_integral', 'autopilot_dgain', 'autopilot_delay', 'autopilot_deadband'}
CLEAN_HEADING = (('shallow', 465715061378216776, {'drag_change': 1.49573188}),
                 ('deep', 3872349389205794781, {'pump_lag': 26.9652148}),
                 ('shallow', 2222927503756928418, {'fin_effectiveness': 1.39663323}),
                 ('shallow', 3092676951293991926, {'drag_change': 1.34282389, 'pump_lag': 11.220744}),
                 ('shallow', 2043783731430036046, {'pitch_trim_offset': 0.104589858}))
HIDDEN_GAIN = (('shallow', 9161994383510207284, {'autopilot_gain': 0.973585885}),
               ('deep', 2632976487017021347, {'autopilot_gain': 2.15113629}))


def autopilot_named(found):
    return sorted(e for e in found if e in AUTOPILOT_LINK)


def main():
    truth, program, source, out = sys.argv[1:5]
    os.makedirs(out, exist_ok=True)
    failures = []
    for variant, seed, effects in CLEAN_HEADING:
        found = diagnose(truth, program, source, out, variant, seed, effects)
        named = autopilot_named(found)
        print('%s %d %s: autopilot link names %s' % (variant, seed, effects, named))
        if named:
            failures.append('clean heading (%s %d) names %s' % (variant, seed, ', '.join(named)))
    for variant, seed, effects in HIDDEN_GAIN:
        found = diagnose(truth, program, source, out, variant, seed, effects)
        gain = effects['autopilot_gain']
        check(failures, found, 'autopilot_gain', gain, 'autopilot_delay')
        f = found.get('autopilot_gain')
        if f is not None and abs(f['value'] - gain) > 0.15 * gain:
            failures.append('autopilot_gain %.3f read %.3f: not within 15 %%' % (gain, f['value']))
        others = [e for e in autopilot_named(found) if e != 'autopilot_gain']
        if others:
            failures.append('hidden autopilot_gain %.3f: also named %s' % (gain, ', '.join(others)))
    return finish(failures, 'autopilot law stepped at unlogged cycles')


if __name__ == '__main__':
    sys.exit(main())
