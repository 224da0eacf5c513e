#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Identifiability stated in the heading plane (the fitting core's screen and
verdict, as in the vertical plane), on a log of the independent truth
simulator with a hidden compass/yaw dead time: a dead time and a slow yaw
pole both make the yaw follow the fin late, so a named yaw_delay must be
judged against yaw_time_constant - told apart by the held-out yos or
ambiguous - and every verdict must follow from the held-out errors it
states (the selection's margins: 3 % and 0.0002 rad/s for the vehicle link).
How often and how well the delay is sized is the coverage benchmark's.

A fresh seed every run (printed; GLIDER_TEST_SEED=N replays it).

  check_heading_ambiguity.py GLIDER_TRUTH GLIDER_DIAGNOSE VEHICLE WORKDIR
"""
import random
import sys

from check_ambiguity import fly_and_diagnose, fresh_seed  # the same truth-then-diagnose step
from screen_checks import stated_under_screen


def verdict_follows(a, absolute):
    """The pair's verdict from its own held-out errors, by the rule of what it was judged on."""
    chosen, alternative = a["chosen_heldout_rms"], a["alternative_heldout_rms"]
    if a["judged_on"] == "heading innovations":
        # The yaw-lag probe's pair (the lag against the delay, each measured beside the fin): no
        # signatures, so no correlation; ambiguous where neither improves on the other by the
        # relative margin (fitting_core::improves_heldout, no absolute margin on innovations).
        if a["correlation"] is not None:
            return False
        ambiguous = not (chosen < 0.97 * alternative) and not (alternative < 0.97 * chosen)
        return ambiguous == (a["verdict"] == "ambiguous")
    if a["judged_on"] != "rate error" or a["correlation"] is None or a["correlation"] < 0.75:
        return False
    ambiguous = alternative <= chosen + max(0.03 * chosen, absolute)
    return ambiguous == (a["verdict"] == "ambiguous")


def main(truth, diagnose, vehicle, workdir):
    seed = fresh_seed()
    delay = random.Random(seed).uniform(5.0, 8.0)
    print(f"seed {seed} (replay: GLIDER_TEST_SEED={seed}): hidden yaw_delay {delay:.2f} s")
    d = fly_and_diagnose(truth, diagnose, vehicle, workdir, seed, "yaw_delay", delay, "heading")
    links = d["heading"]["links"]
    for name, link in links.items():
        print(name, "findings:", [(f["effect"], round(f["value"], 4)) for f in link["findings"]])
        print(name, "identifiability:", [(a["chosen"], a["alternative"], a["verdict"], a["judged_on"],
                                          None if a["correlation"] is None else round(a["correlation"], 3),
                                          round(a["chosen_heldout_rms"], 6), round(a["alternative_heldout_rms"], 6))
                                         for a in link["identifiability"]])
        absolute = 0.0002 if name == "vehicle" else 0.002
        for a in link["identifiability"]:
            if not verdict_follows(a, absolute):
                print("FAIL: a verdict that its own numbers contradict")
                return 1
    vehicle_link = links["vehicle"]
    named = {f["effect"] for f in vehicle_link["findings"]}
    if "yaw_delay" not in named:
        print("NOTE: yaw_delay not named in this draw (a coverage miss, counted by the benchmark)")
        print("PASS heading identifiability judged (nothing to judge)")
        return 0
    pair = {"yaw_delay", "yaw_time_constant"}
    if not any({a["chosen"], a["alternative"]} == pair for a in vehicle_link["identifiability"]) and \
            "yaw_time_constant" not in named:
        # Not judged is allowed only where the link states why: the pair's signatures correlate under the
        # screen (identifiability_screen), with the other findings projected out.
        screen = vehicle_link.get("identifiability_screen", {})
        under = stated_under_screen(screen, pair, "chosen", "correlation")
        if under is None:
            print("FAIL: the yaw_delay / yaw_time_constant pair is decided silently")
            return 1
        print(f"NOTE: the pair is not judged: its signatures correlate {under:.3f}, under the "
              f"screen {screen['screen_correlation']} (stated in identifiability_screen)")
    print("PASS heading identifiability judged")
    return 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
