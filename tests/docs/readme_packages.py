#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""README's "What they install" package lists are the `./glider` script's own
arrays (BUILD_PACKAGES, REPORT_PACKAGES, ...), not a copy kept by hand: the
text between the two markers in README.md is generated from them.

  readme_packages.py SOURCE_DIR           check (CTest docs.readme_packages)
  readme_packages.py SOURCE_DIR --write   regenerate README.md's lists
"""
import re
import subprocess
import sys

BEGIN = "<!-- packages: generated from ./glider's lists by tests/docs/readme_packages.py --write -->"
END = "<!-- end of packages -->"
LISTS = ("BUILD_PACKAGES", "REPORT_PACKAGES", "TEST_PACKAGES", "CAMPAIGN_PACKAGES", "SHORE_PACKAGES", "BENCH_PACKAGES",
         "CROSS_PACKAGES")


def package_lists(source_dir):
    """{LIST: [package, ...]} read by bash from the sourced script (its main does not run)."""
    script = "source ./glider; " + "; ".join(f'echo "{name}=${{{name}[*]}}"' for name in LISTS)
    out = subprocess.run(["bash", "-c", script], cwd=source_dir, capture_output=True, text=True, timeout=30, check=True)
    lists = {}
    for line in out.stdout.splitlines():
        name, _, packages = line.partition("=")
        lists[name] = packages.split()
    missing = [name for name in LISTS if not lists.get(name)]
    if missing:
        raise SystemExit(f"FAIL readme_packages: ./glider defines no {', '.join(missing)}")
    return lists


def names(packages):
    return ", ".join(f"`{p}`" for p in packages)


def generated(lists):
    return "\n".join([
        BEGIN,
        "- `./glider demo` (and `sil`, `steady`, `diagnose`, `bench`, `build`, ...): the build dependencies only "
        f"(BUILD_PACKAGES): {names(lists['BUILD_PACKAGES'])}. Never a kernel.",
        "- `./glider diagnose --report`, `diagnose-real`, `validate`, `heading-study` add the plotting packages "
        f"(REPORT_PACKAGES): {names(lists['REPORT_PACKAGES'])}.",
        "- `./glider regress`, `campaign`, `fleet` add (CAMPAIGN_PACKAGES): "
        f"{names(lists['CAMPAIGN_PACKAGES'])}; `./glider benchmark` adds (BENCH_PACKAGES): "
        f"{names(lists['BENCH_PACKAGES'])}; `./glider shore` adds (SHORE_PACKAGES): {names(lists['SHORE_PACKAGES'])}.",
        "- `./glider test`: all of those but BENCH_PACKAGES and SHORE_PACKAGES, and the tests' peers and checkers (TEST_PACKAGES): "
        f"{names(lists['TEST_PACKAGES'])}.",
        "- `./glider cross` and the arm64 stage of `./glider test` (after `dpkg --add-architecture arm64`; "
        f"CROSS_PACKAGES): {names(lists['CROSS_PACKAGES'])}.",
        END])


def main(argv):
    if len(argv) not in (1, 2) or (len(argv) == 2 and argv[1] != "--write"):
        print(__doc__.strip().splitlines()[-2].strip(), file=sys.stderr)
        return 2
    source_dir = argv[0]
    readme_path = f"{source_dir}/README.md"
    with open(readme_path, encoding="utf-8") as f:
        readme = f.read()
    block = re.compile(re.escape(BEGIN) + ".*?" + re.escape(END), re.DOTALL)
    found = block.search(readme)
    if not found:
        print(f"FAIL readme_packages: README.md has no block between '{BEGIN}' and '{END}'")
        return 1
    want = generated(package_lists(source_dir))
    if len(argv) == 2:
        with open(readme_path, "w", encoding="utf-8") as f:
            f.write(readme[:found.start()] + want + readme[found.end():])
        print("README.md: package lists written")
        return 0
    if found.group(0) != want:
        print("FAIL readme_packages: README.md's package lists differ from ./glider's arrays; regenerate with\n"
              f"  python3 tests/docs/readme_packages.py . --write\nwant:\n{want}\nhave:\n{found.group(0)}")
        return 1
    print("PASS readme_packages")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
