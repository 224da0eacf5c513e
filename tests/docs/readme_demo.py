#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""README's demo summary is what `./glider demo` prints: every line but the
wall time and the real-time factor (measured, they vary with the load) is
deterministic and checked here against glider-sil flying the demo mission.

  readme_demo.py SOURCE_DIR GLIDER_SIL           check (CTest docs.readme_demo)
  readme_demo.py SOURCE_DIR GLIDER_SIL --write   rewrite README's deterministic lines
"""
import os
import re
import subprocess
import sys
import tempfile

MEASURED = re.compile(r"^\s*(wall time|real-time factor)\s*:")


def demo_summary(source_dir, sil):
    """The demo's summary lines, with the log path README shows (build/demo/demo_flight.csv)."""
    with tempfile.TemporaryDirectory(prefix="readme_demo_") as tmp:
        log = os.path.join(tmp, "demo_flight.csv")
        out = subprocess.run([sil, "--mission", "boards/missions/demo_yo.toml", "--out", log], cwd=source_dir,
                             capture_output=True, text=True, timeout=60, check=True).stdout
    return out.replace(log, "build/demo/demo_flight.csv").rstrip("\n").split("\n")


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__.strip().splitlines()[-2].strip(), file=sys.stderr)
        return 2
    source_dir, sil = os.path.abspath(argv[0]), os.path.abspath(argv[1])
    path = os.path.join(source_dir, "README.md")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    block = re.search(r"\n```\n(SIL flight: boards/missions/demo_yo\.toml.*?)\n```\n", text, re.DOTALL)
    if not block:
        print("FAIL readme_demo: README.md has no ``` block starting 'SIL flight: boards/missions/demo_yo.toml'")
        return 1
    have = block.group(1).split("\n")
    want = demo_summary(source_dir, sil)
    if len(have) != len(want):
        print("FAIL readme_demo: README shows %d lines, the demo prints %d:\n%s" % (len(have), len(want), "\n".join(want)))
        return 1
    merged, wrong = [], []
    for doc_line, run_line in zip(have, want):
        if MEASURED.match(doc_line) and MEASURED.match(run_line):
            merged.append(doc_line)  # measured on the build machine, stated as such in README
        else:
            merged.append(run_line)
            if doc_line != run_line:
                wrong.append("README: %r\n  demo: %r" % (doc_line, run_line))
    if len(argv) == 3 and argv[2] == "--write":
        with open(path, "w", encoding="utf-8") as f:
            f.write(text[:block.start(1)] + "\n".join(merged) + text[block.end(1):])
        print("README.md: %d demo summary lines rewritten" % len(wrong))
        return 0
    for line in wrong:
        print(line)
    if wrong:
        print("FAIL readme_demo: regenerate with python3 tests/docs/readme_demo.py . build/release/sil/glider-sil --write")
        return 1
    print("%d deterministic lines as ./glider demo prints them\nPASS readme_demo" % (len(want) - 2))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
