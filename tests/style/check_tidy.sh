#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# style.tidy: clang-tidy with the repository's .clang-tidy on the flight code:
# firmware/ (the flight software and the Linux executable) and hal/ (the HAL,
# core library and Linux drivers), every kept check an error. model/, sil/ and
# tools/ are not enforced yet: their findings are listed in docs/architecture.md
# and the scope grows as they are fixed (the two regexes below). Uses the build's
# compile_commands.json; runs the files in parallel.
#   check_tidy.sh SOURCE_DIR BUILD_DIR [RUN_CLANG_TIDY]
set -euo pipefail
source_dir="${1:?usage: check_tidy.sh SOURCE_DIR BUILD_DIR [RUN_CLANG_TIDY]}"
build_dir="${2:?usage: check_tidy.sh SOURCE_DIR BUILD_DIR [RUN_CLANG_TIDY]}"
runner="${3:-run-clang-tidy}"
[ -f "$build_dir/compile_commands.json" ] || { echo "check_tidy: no $build_dir/compile_commands.json" >&2; exit 1; }
log="$build_dir/clang-tidy.log"
start=$(date +%s)
# -quiet: only diagnostics; WarningsAsErrors in .clang-tidy makes each one an error.
set +e
# The header filter is anchored at the source tree (boost/math/tools/... must not match "tools/").
"$runner" -p "$build_dir" -quiet -j "$(nproc)" -header-filter="^$source_dir/(firmware|hal)/" \
  "^$source_dir/(firmware|hal)/" > "$log" 2>&1
status=$?
set -e
errors=$(grep -cE '(warning|error): .*\[[a-z0-9.-]+(,[a-z0-9.-]+)*\]$' "$log" || true)
files=$(python3 -c "import json,re,sys; print(sum(1 for e in json.load(open('$build_dir/compile_commands.json')) if re.match(r'^$source_dir/(firmware|hal)/', e['file'])))")
echo "check_tidy: $files files, $(( $(date +%s) - start )) s, $errors finding(s); full output in $log"
if [ "$status" -ne 0 ] || [ "$errors" -ne 0 ]; then
  grep -E '(warning|error): ' "$log" | sort -u | head -n 60 >&2
  exit 1
fi
