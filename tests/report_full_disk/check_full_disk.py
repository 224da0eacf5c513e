#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""glider-diagnose --report DIR on a full disk (issue 28): exit 1 naming the
file it could not write, and no empty, cut or half-written file left behind
(each file goes to a temporary name, is checked, then renamed; a PNG that
gnuplot left empty is removed). The full disk is a small tmpfs: mounting needs
CAP_SYS_ADMIN (./glider test runs as root); where it is refused the test
cannot run and exits 77 (CTest: skipped).

  check_full_disk.py GLIDER_DIAGNOSE LOG WORK_DIR
"""
import os
import re
import shutil
import subprocess
import sys


def fail(message):
    print("FAIL report_full_disk: " + message)
    sys.exit(1)


def diagnose(tool, log, report, plane):
    args = [tool, log, "--plane", plane, "--report", report]
    if plane == "vertical":
        args += ["--model", "steady"]
    return subprocess.run(args, capture_output=True, text=True, timeout=50)


def check_left(report):
    for name in os.listdir(report):
        path = os.path.join(report, name)
        if name.endswith(".partial"):
            fail("%s: a temporary file was left behind" % path)
        if os.path.getsize(path) == 0:
            fail("%s: an empty file was left behind" % path)
        if name.endswith(".png") and not open(path, "rb").read().endswith(b"IEND\xaeB`\x82"):
            fail("%s: a cut PNG was left behind" % path)


def full_disk(tool, log, mount_dir, size_bytes, plane, expected_file):
    size_kib = (size_bytes + 4095) // 4096 * 4
    os.makedirs(mount_dir, exist_ok=True)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=%dk" % size_kib, "tmpfs", mount_dir],
                      capture_output=True).returncode != 0:
        print("SKIP report_full_disk: no tmpfs mount here: the full disk is not tested")
        sys.exit(77)
    try:
        report = os.path.join(mount_dir, "report")
        run = diagnose(tool, log, report, plane)
        print("%s plane, %d KiB disk: exit %d: %s" % (plane, size_kib, run.returncode, run.stderr.strip()[-300:]))
        if run.returncode != 1:
            fail("%s plane on a %d KiB disk: exit %d, expected 1" % (plane, size_kib, run.returncode))
        if not re.search(re.escape(report) + "/" + expected_file + ": cannot write", run.stderr):
            fail("the refusal does not name %s/%s" % (report, expected_file))
        check_left(report)
    finally:
        subprocess.run(["umount", mount_dir])


def main():
    tool, log, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    # On a disk with room: the sizes the files take (heading plane: two files).
    roomy = os.path.join(work, "roomy")
    run = diagnose(tool, log, roomy, "heading")
    if run.returncode != 0:
        fail("heading plane with room: exit %d: %s" % (run.returncode, run.stderr))
    check_left(roomy)
    json_bytes = os.path.getsize(os.path.join(roomy, "diagnosis.json"))
    # Room for diagnosis.json only: the extended vehicle file is the one refused.
    full_disk(tool, log, os.path.join(work, "mnt"), json_bytes, "heading", "extended_vehicle.toml")
    # No room at all: the first data file of the vertical report.
    full_disk(tool, log, os.path.join(work, "mnt"), 4096, "vertical", "samples.dat")
    # Room for the data but not every plot: gnuplot exits 0 leaving an empty PNG.
    full_disk(tool, log, os.path.join(work, "mnt"), 400 * 1024, "vertical", r"\w+\.png")
    print("PASS report_full_disk")


if __name__ == "__main__":
    main()
