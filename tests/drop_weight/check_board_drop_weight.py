#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The drop weight on the target, through the shipped board file: a board
with a [gpio] board (the leak line and the burn wire) has the drop weight
fitted and every abort releases it; the same board without [gpio] has none.
glider-firmware --check-mission says which (the release itself through the
GPIO line is the GPIO driver's kernel test, gpio.kernel_*, and the abort
sequence's command the unit tests; the SIL path is sil.summary_json, the
HIL harness checks what the plant's board says).

  check_board_drop_weight.py GLIDER_FIRMWARE SOURCE_DIR OUT_DIR
"""
import os
import re
import subprocess
import sys


def fail(message):
    print("FAIL board_drop_weight: " + message)
    sys.exit(1)


def said(firmware, board, mission):
    proc = subprocess.run([firmware, "--board", board, "--mission", mission, "--check-mission"], timeout=60,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if proc.returncode != 0:
        fail("%s: exit %d: %s" % (board, proc.returncode, proc.stderr))
    m = re.findall(r"glider-firmware: drop weight: (.*)", proc.stderr)
    if len(m) != 1:
        fail("%s: no single 'drop weight:' line in %r" % (board, proc.stderr))
    return m[0]


def main():
    firmware, source, out_dir = sys.argv[1:4]
    os.makedirs(out_dir, exist_ok=True)
    board = os.path.join(source, "boards/target/cm4_glider.toml")
    mission = os.path.join(source, "boards/missions/demo_yo.toml")
    got = said(firmware, board, mission)
    if got != "fitted, released by every abort":
        fail("boards/target/cm4_glider.toml (with [gpio]): drop weight: %s" % got)

    # The same board without its [gpio] table; its other relative paths made absolute.
    with open(board) as f:
        text = f.read()
    gpio = re.search(r"^\[gpio\]\nboard = \"[^\"]*\"\n", text, re.M)
    if gpio is None:
        fail("boards/target/cm4_glider.toml: no [gpio] table to remove")
    text = text[:gpio.start()] + text[gpio.end():]
    text = text.replace('"../', '"' + os.path.join(source, "boards") + "/")
    no_gpio = os.path.join(out_dir, "cm4_glider_no_gpio.toml")
    with open(no_gpio, "w") as f:
        f.write(text)
    got = said(firmware, no_gpio, mission)
    if got != "not fitted (the board has no [gpio])":
        fail("cm4_glider.toml without [gpio]: drop weight: %s" % got)
    print("PASS board_drop_weight")


if __name__ == "__main__":
    main()
