# SPDX-License-Identifier: Apache-2.0
"""The HIL mission of the end-to-end tests (tests/hil/waypoint), shared by
check_hil_e2e.py (HIL) and check_sil_hil_same.py (the same mission in SIL):
the keystroke wait made 100 s so the shore has time to work; case "goto":
a surfacing every 3 yos, the pilot's goto_l10.ma (a waypoint 620 m north of
the launch point) and a truncated copy of it to queue."""
import os
import shutil

NEW_WPT = (5419.3000, 724.5880)  # goto case: DDMM.MMMM lat, lon; 620 m north of the launch point


def prepare(source, work, case):
    """Copies and edits the mission under work/mission; returns (mi, goto, broken) paths."""
    mission = os.path.join(work, "mission")
    shutil.copytree(os.path.join(source, "tests/hil/waypoint"), mission)
    mi = os.path.join(mission, "missions/hil.mi")
    text = open(mi).read()
    old = "b_arg: end_action(enum)          2   # resume"
    assert old in text
    open(mi, "w").write(text.replace(old, "b_arg: end_action(enum)          1   # wait for the pilot, then resume\n"
                                          "    b_arg: keystroke_wait_time(s)  100"))
    if case == "goto":
        # A surfacing every 3 yos (about 500 s), not every when_secs: when_secs counts from the previous
        # surfacing (docs/comms.md), so the time a call holds the vehicle up would shorten the next dive, and a
        # call's simulated length differs between HIL (wall time x 100) and SIL (lockstep with the shore).
        yo = os.path.join(mission, "mafiles/yo10.ma")
        text = open(yo).read()
        old = "b_arg: num_half_cycles_to_do(nodim) -1   # until the waypoint"
        assert old in text
        open(yo, "w").write(text.replace(old, "b_arg: num_half_cycles_to_do(nodim)  6   # 3 yos, then surface"))
    goto = os.path.join(work, "goto_l10.ma")
    ga = open(os.path.join(mission, "mafiles/goto_l10.ma")).read()
    assert "724.7266 5418.9660" in ga
    open(goto, "w").write(ga.replace("724.7266 5418.9660", "%.4f %.4f" % (NEW_WPT[1], NEW_WPT[0])))
    os.makedirs(os.path.join(work, "broken"))
    broken = os.path.join(work, "broken", "goto_l10.ma")
    open(broken, "w").write(open(goto).read().split("<end:b_arg>")[0])
    return mission, mi, goto, broken
