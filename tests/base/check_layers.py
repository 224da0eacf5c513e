#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The floors of docs/architecture.md hold: an include and a library link only
ever point down (or stay on the same floor), and the two middle floors (model/
and firmware/) do not use each other; tools/ holds only wings, each listing its
folders in its README.md. Reads the sources and CMakeLists.txt as
text; exits 1 naming each file:line that points up."""
import os
import re
import sys

ROOT = sys.argv[1]
# Floor of a path (first match wins): ground, physics | flight, mains, tools, users.
FLOORS = [("hal/core/", 1, "ground"), ("hal/", 1, "ground"), ("model/", 2, "physics"),
          ("firmware/linux/", 3, "mains"), ("firmware/", 2, "flight"), ("sil/", 3, "mains"),
          ("tools/", 4, "tools"), ("benchmarks/", 5, "users"), ("tests/", 5, "users")]


def floor_of(rel):
    for prefix, rank, name in FLOORS:
        if rel.startswith(prefix):
            return rank, name
    return None


def files(suffixes):
    for top in ("hal", "model", "firmware", "sil", "tools", "benchmarks", "tests"):
        for dirpath, dirnames, filenames in os.walk(os.path.join(ROOT, top)):
            dirnames[:] = [d for d in dirnames if d not in ("build", "__pycache__")]
            for f in filenames:
                if f.endswith(suffixes):
                    yield os.path.relpath(os.path.join(dirpath, f), ROOT)


def allowed(own, other):
    (rank, name), (other_rank, other_name) = own, other
    if {name, other_name} == {"physics", "flight"}:
        return False  # the model and the flight software meet only in sil/ (and tests)
    return other_rank <= rank


# Where each project header lives: "glider/x/y.hpp" -> the file under some include/ dir.
headers = {}
for rel in files((".hpp", ".h")):
    m = re.search(r"/include/(glider/.+)$", rel)
    if m:
        headers.setdefault(m.group(1), rel)
# Where each library is defined.
libraries = {}
cmake_files = [rel for rel in files(("CMakeLists.txt",))]
for rel in cmake_files:
    for m in re.finditer(r"add_library\(\s*(glider_\w+)", open(os.path.join(ROOT, rel)).read()):
        libraries.setdefault(m.group(1), os.path.dirname(rel) + "/")

problems = []
checked = 0
for rel in files((".cpp", ".hpp", ".h")):
    own = floor_of(rel)
    if own is None or own[0] == 5:
        continue
    for number, line in enumerate(open(os.path.join(ROOT, rel), errors="replace"), 1):
        m = re.match(r'\s*#\s*include\s+"(glider/[^"]+)"', line)
        if not m or m.group(1) not in headers:
            continue
        checked += 1
        other = floor_of(headers[m.group(1)])
        if other and not allowed(own, other):
            problems.append(f"{rel}:{number}: {own[1]} includes {m.group(1)} ({other[1]}, {headers[m.group(1)]})")
for rel in cmake_files:
    own = floor_of(rel)
    if own is None or own[0] == 5:
        continue
    text = open(os.path.join(ROOT, rel)).read()
    for m in re.finditer(r"target_link_libraries\(([^)]*)\)", text):
        number = text.count("\n", 0, m.start()) + 1
        words = m.group(1).split()
        for name in [w for w in words[1:] if re.fullmatch(r"glider_\w+", w)]:
            if name not in libraries:
                continue
            checked += 1
            other = floor_of(libraries[name])
            if other and not allowed(own, other):
                problems.append(f"{rel}:{number}: {own[1]} links {name} ({other[1]}, {libraries[name]})")
# The wings of floor 4 (docs/architecture.md): every folder under tools/ is a wing, and every folder in a
# wing is listed (as `name/`) in the wing's README.md, so new code lands in the wing of its job.
WINGS = ("files", "science", "hardware", "shore", "fleet")


def folders(path):
    """Sub-folders holding a file (a folder left with only __pycache__ or build/ output does not count)."""
    found = []
    for name in sorted(os.listdir(path)):
        full = os.path.join(path, name)
        if os.path.isdir(full) and name not in ("build", "__pycache__") and any(
                files_here for d, _, files_here in os.walk(full) if "__pycache__" not in d.split(os.sep)):
            found.append(name)
    return found


tools = os.path.join(ROOT, "tools")
# Beside the wings only their CMakeLists.txt and README.md (a source left at a wing's root after a merge,
# e.g. tools/shore/x.cpp from before the station moved, belongs in a folder of the wing).
for wing in [""] + [w for w in WINGS if os.path.isdir(os.path.join(tools, w))]:
    for name in sorted(os.listdir(os.path.join(tools, wing))):
        if os.path.isfile(os.path.join(tools, wing, name)) and name not in ("CMakeLists.txt", "README.md"):
            problems.append(f"{os.path.join('tools', wing, name)}: a file beside the wings; it belongs in a folder "
                            "of its wing")
for name in folders(tools):
    checked += 1
    if name not in WINGS:
        problems.append(f"tools/{name}/: not a wing ({', '.join(WINGS)}): new code goes into the wing of its job")
        continue
    readme = os.path.join(tools, name, "README.md")
    listed = open(readme).read() if os.path.exists(readme) else ""
    for sub in folders(os.path.join(tools, name)):
        checked += 1
        if f"`{sub}/`" not in listed:
            problems.append(f"tools/{name}/README.md: does not list `{sub}/` (one line: what it holds)")
for p in problems:
    print(p)
if problems:
    print(f"FAIL layers: {len(problems)} of {checked} includes, links and tools/ folders out of place")
    sys.exit(1)
print(f"PASS layers: {checked} includes and links point down or sideways, tools/ folders in their wings")
