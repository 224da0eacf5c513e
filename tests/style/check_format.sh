#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# style.format: every C++ source of the project is formatted as .clang-format says.
# Fails listing the files to fix; `clang-format -i FILE` fixes one. Uses the
# files git tracks (plus untracked, not ignored ones) so build trees are never read.
set -euo pipefail
root="${1:?usage: check_format.sh SOURCE_DIR [CLANG_FORMAT]}"
clang_format="${2:-clang-format}"
cd "$root"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard -- '*.cpp' '*.hpp' '*.h' '*.cc' |
                       while read -r f; do [ -f "$f" ] && echo "$f"; done)
else
  mapfile -t files < <(find . -path ./build -prune -o -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print)
fi
[ ${#files[@]} -gt 0 ] || { echo "check_format: no C++ files found under $root" >&2; exit 1; }
bad=()
for f in "${files[@]}"; do
  "$clang_format" --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
echo "check_format: ${#files[@]} files checked with $("$clang_format" --version | head -n 1)"
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format: ${#bad[@]} file(s) not formatted (run: clang-format -i FILE):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
