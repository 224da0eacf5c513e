#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-sil --summary-json end to end: a complete, an aborted and a stopped
run, and a .mi mission with waypoints; every documented key present with the
right type, the values consistent with the run and with the exit code.

  check_summary_json.py GLIDER_SIL SOURCE_DIR OUT_DIR
"""
import json
import os
import subprocess
import sys

KEYS = {
    "schema": str, "mission_file": str, "vehicle_file": str, "seed": int, "result": str,
    "stop_reason": (str, type(None)), "abort": (dict, type(None)), "yos": int, "max_depth_m": float,
    "segments": int, "waypoint_list_length": int, "waypoint_radius_m": (float, type(None)),
    "waypoints_reached": int, "waypoints": list, "surfacings": list,
    "dr_error_m_per_km": (float, type(None)), "dr_error_max_m": (float, type(None)),
    "dives": dict, "climbs": dict, "energy_kj": float, "charge_ah": float, "distance_km": float,
    "sim_time_s": float, "wall_time_s": float, "cycles": int, "loop_overruns": int, "log_rows": int,
    "log_rows_lost": int,
}
GLIDE_KEYS = ["settled_samples", "mean_pitch_deg", "mean_depth_rate_m_s", "pitch_error_samples",
              "max_pitch_error_deg", "rms_pitch_error_deg"]


def fail(message):
    print("FAIL summary_json: " + message)
    sys.exit(1)


def run(sil, out_dir, name, args, expected_code):
    path = os.path.join(out_dir, name + ".json")
    if os.path.exists(path):
        os.remove(path)
    proc = subprocess.run([sil, "--quiet", "--summary-json", path] + args, timeout=120,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != expected_code:
        fail("%s: exit %d, expected %d: %s" % (name, proc.returncode, expected_code, proc.stderr))
    with open(path) as f:
        summary = json.load(f)
    for key, kind in KEYS.items():
        if key not in summary:
            fail("%s: key %s missing" % (name, key))
        if not isinstance(summary[key], kind) or isinstance(summary[key], bool):
            fail("%s: %s is %r" % (name, key, summary[key]))
    if list(summary.keys())[:len(KEYS)] != list(KEYS.keys()):
        fail("%s: key order changed: %s" % (name, list(summary.keys())))
    for glide in ("dives", "climbs"):
        for key in GLIDE_KEYS:
            if key not in summary[glide]:
                fail("%s: %s.%s missing" % (name, glide, key))
    if summary["schema"] != "glider-sil-summary/1":
        fail("%s: schema %s" % (name, summary["schema"]))
    return summary


def main():
    sil, source, out_dir = sys.argv[1:4]
    os.makedirs(out_dir, exist_ok=True)
    vehicle = ["--vehicle", os.path.join(source, "boards/vehicles/slocum_we01.toml")]
    demo = ["--mission", os.path.join(source, "boards/missions/demo_yo.toml")] + vehicle

    s = run(sil, out_dir, "complete", demo, 0)
    if s["result"] != "complete" or s["abort"] is not None or s["yos"] != 3 or s["stop_reason"] is not None:
        fail("complete run: %s %s yos %d" % (s["result"], s["abort"], s["yos"]))
    if not (45.0 < s["max_depth_m"] < 56.0) or s["dives"]["pitch_error_samples"] == 0:
        fail("complete run: max depth %g, pitch samples %d" % (s["max_depth_m"], s["dives"]["pitch_error_samples"]))
    rms, worst = s["dives"]["rms_pitch_error_deg"], s["dives"]["max_pitch_error_deg"]
    if not (0.0 < rms <= worst):
        fail("complete run: rms pitch error %g not in (0, max %g]" % (rms, worst))

    s = run(sil, out_dir, "aborted", demo + ["--fault", "leak@600s"], 3)
    abort = s["abort"]
    if s["result"] != "aborted" or abort is None or abort["cause"] != "leak":
        fail("aborted run: %s %s" % (s["result"], abort))
    if not (600.0 <= abort["time_s"] <= 602.0) or abort["surfaced_after_s"] is None:
        fail("aborted run: abort at %s, surfaced after %s" % (abort["time_s"], abort["surfaced_after_s"]))
    # The drop weight through the shipped path: slocum_we01.toml's [fitted]
    # drop_weight = true releases it on the abort; the same vehicle file with
    # drop_weight = false (nothing else changed) keeps it.
    if abort["drop_weight_released"] is not True:
        fail("aborted run: slocum_we01 ([fitted] drop_weight = true): drop_weight_released %r"
             % abort["drop_weight_released"])
    with open(os.path.join(source, "boards/vehicles/slocum_we01.toml")) as f:
        text = f.read()
    if text.count("\ndrop_weight = true\n") != 1:
        fail("boards/vehicles/slocum_we01.toml: no single '[fitted] drop_weight = true' line to turn off")
    no_weight = os.path.join(out_dir, "we01_no_drop_weight.toml")
    with open(no_weight, "w") as f:
        f.write(text.replace("\ndrop_weight = true\n", "\ndrop_weight = false\n"))
    s = run(sil, out_dir, "aborted_no_drop_weight", ["--mission", os.path.join(source, "boards/missions/demo_yo.toml"),
                                                      "--vehicle", no_weight, "--fault", "leak@600s"], 3)
    if s["abort"] is None or s["abort"]["cause"] != "leak" or s["abort"]["drop_weight_released"] is not False:
        fail("aborted run, drop_weight = false: %s" % s["abort"])

    s = run(sil, out_dir, "stopped", demo + ["--max-sim-time-s", "300"], 3)
    if s["result"] != "stopped" or s["stop_reason"] != "max_sim_time" or s["sim_time_s"] > 302.0:
        fail("stopped run: %s %s at %g s" % (s["result"], s["stop_reason"], s["sim_time_s"]))

    box = [os.path.join(source, "boards/missions/box_current/missions/box.mi"), "--max-working-depth-m", "200",
           "--legs", "1"] + vehicle
    s = run(sil, out_dir, "waypoints", box, 0)
    if s["waypoints_reached"] < 1 or len(s["waypoints"]) != s["waypoints_reached"]:
        fail("box mission: %d reached, %d events" % (s["waypoints_reached"], len(s["waypoints"])))
    w = s["waypoints"][0]
    if w["index"] != 0 or not (w["true_distance_m"] < 2 * s["waypoint_radius_m"]):
        fail("box mission: first waypoint event %s" % w)
    if len(s["surfacings"]) < 2 or s["dr_error_m_per_km"] is None:
        fail("box mission: surfacings %s" % s["surfacings"])
    print("PASS summary_json")


if __name__ == "__main__":
    main()
