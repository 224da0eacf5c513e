#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""One flight application, two mains: glider-sil and glider-firmware accept or
refuse the same mission files identically, with the same file:line messages
(issue 12). Both run --check-mission (nothing flown, no device opened) on good
missions and on bad ones made from the shipped box mission and demo TOML.

  check_same_missions.py GLIDER_SIL GLIDER_FIRMWARE SOURCE_DIR
"""
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile


def fail(message):
    print("FAIL same_missions: " + message)
    sys.exit(1)


def run(command, vehicle_data):
    proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=60)
    # The program's own name and its "accepted for <vehicle|board>" line differ by design.
    lines = []
    for line in proc.stderr.splitlines():
        line = re.sub(r"^glider-(sil|firmware): ", "", line)
        line = re.sub(r": mission accepted for (vehicle|board) .*$", ": mission accepted", line)
        # Where the vehicle's data came from (vehicle file / board file) is named as such.
        line = line.replace(vehicle_data, "<vehicle data>")
        # The firmware also says whether its board fits a drop weight (from the board's
        # [gpio]; linux.board_drop_weight checks that line): not a mission message.
        if line.startswith("drop weight: "):
            continue
        lines.append(line)
    return proc.returncode, lines


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def mutate(source_dir, tmp, name, mi_edit=None, ma_edit=None):
    """A copy of boards/missions/box_current with one edit: returns the .mi path."""
    root = os.path.join(tmp, name)
    shutil.copytree(os.path.join(source_dir, "boards/missions/box_current"), root)
    mi = os.path.join(root, "missions/box.mi")
    if mi_edit:
        with open(mi) as f:
            text = f.read()
        write(mi, mi_edit(text))
    if ma_edit:
        ma = os.path.join(root, "mafiles/yo10.ma")
        with open(ma) as f:
            text = f.read()
        write(ma, ma_edit(text))
    return mi


def main():
    sil, firmware, source = sys.argv[1:4]
    with open(os.path.join(source, "boards/actuators/default_modbus.toml")) as f:
        actuators = f.read()
    with tempfile.TemporaryDirectory(prefix="same_missions_") as tmp:
        # A board whose [vehicle] is the SIL vehicle's (slocum_we01) with every device fitted.
        write(os.path.join(tmp, "actuators.toml"), actuators + (
            "\n[rudder]\nslave = 1\nbase_address = 64\ncounts_per_unit = 10\ntravel_min_deg = -30.0\n"
            "travel_max_deg = 30.0\nmin_deg = -27.0\nmax_deg = 27.0\nrate_deg_s = 5.0\nmax_rate_deg_s = 10.0\n"))
        board = os.path.join(tmp, "board.toml")
        write(board, (
            'name = "same_missions"\n'
            '[vehicle]\nmax_working_depth_m = 200.0\nballast_min_cc = -250.0\nballast_max_cc = 250.0\n'
            'battery_min_in = -1.0\nbattery_max_in = 1.0\nfin_max_deg = %r\nfin_rate_deg_s = %r\n'
            'yaw_gain_per_m = 0.15\n'
            '[actuators]\nboard = "actuators.toml"\n[gpio]\nboard = "%s/boards/gpio/cm4_glider.toml"\n'
            '[gps]\ndevice = "/dev/null"\n[compass]\ndevice = "/dev/null"\n[depth]\ndevice = "/dev/null"\n'
            '[power]\nhwmon_name = "ina219"\n') % (math.degrees(0.47), math.degrees(0.1), source))
        vehicle = os.path.join(source, "boards/vehicles/slocum_we01.toml")
        demo = os.path.join(source, "boards/missions/demo_yo.toml")
        with open(demo) as f:
            demo_text = f.read()
        bad_toml = os.path.join(tmp, "bad_key.toml")
        write(bad_toml, demo_text.replace("[safety]\n", "[safety]\nsensor_timout_s = 5.0\n"))
        bad_pitch = os.path.join(tmp, "bad_pitch.toml")
        write(bad_pitch, demo_text.replace("dive_pitch_deg = -26.0", "dive_pitch_deg = 26.0"))
        limits = os.path.join(tmp, "bad_limits.toml")
        write(limits, demo_text.replace("ballast_max_cc = 250.0", "ballast_max_cc = 400.0"))
        cases = [
            ("box.mi", os.path.join(source, "boards/missions/box_current/missions/box.mi"), 0),
            ("demo_yo.toml", demo, 0),
            ("heading_hold.mi", os.path.join(source, "boards/missions/heading_hold.mi"), 0),
            ("overdepth beyond rating", mutate(source, tmp, "deep", mi_edit=lambda t: t.replace(
                "overdepth(m)                 60", "overdepth(m)                300")), 0),  # a warning: the rating applies
            ("dive beyond overdepth", mutate(source, tmp, "dive", ma_edit=lambda t: t.replace(
                "d_target_depth(m)            40", "d_target_depth(m)            70")), 1),
            ("missing .ma", mutate(source, tmp, "nofile", mi_edit=lambda t: t.replace(
                "behavior: yo\n    b_arg: args_from_file(enum)     10", "behavior: yo\n    b_arg: args_from_file(enum)     77")), 1),
            ("no abend", mutate(source, tmp, "noabend", mi_edit=lambda t: t.replace("behavior: abend", "behavior: abendx")), 1),
            ("bad number", mutate(source, tmp, "nan", ma_edit=lambda t: t.replace("-0.4537", "-0.45x37")), 1),
            ("toml unknown key", bad_toml, 1),
            ("toml dive pitch up", bad_pitch, 1),
            ("toml limits beyond the vehicle", limits, 1),
        ]
        for name, mission, expected in cases:
            sil_code, sil_lines = run([sil, "--vehicle", vehicle, "--max-working-depth-m", "200", "--mission", mission,
                                       "--check-mission"], vehicle)
            fw_code, fw_lines = run([firmware, "--board", board, "--mission", mission, "--check-mission"], board)
            if sil_code != expected or fw_code != expected:
                fail("%s: exit sil %d firmware %d, expected %d\n  sil: %s\n  firmware: %s"
                     % (name, sil_code, fw_code, expected, sil_lines, fw_lines))
            if sil_lines != fw_lines:
                fail("%s: messages differ\n  sil:      %s\n  firmware: %s" % (name, sil_lines, fw_lines))
            if expected == 1 and not any(re.search(r"\.(mi|ma|toml)(:\d+)?", l) for l in sil_lines):
                fail("%s: refusal does not name the file: %s" % (name, sil_lines))
            print("same: %-32s exit %d  %s" % (name, expected, sil_lines[-1] if sil_lines else ""))
    print("PASS same_missions")


if __name__ == "__main__":
    main()
