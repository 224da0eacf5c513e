#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Issue 26's speed goals (docs/science.md, "Speed beside the coverage"): one real segment diagnosed in both
# planes (comet-2016-174-05, slocum_shallow, --json) under 5 s of CPU, and the 24 h, 1 Hz SIL log (vertical
# plane) under 2 s of CPU, also without its Reynolds exponent line (flown with the prior, as a real log is).
# CPU (user) and wall apart: on a shared machine the wall time is mostly the others' load.
#
#   benchmarks/diagnose_speed.sh BUILD_DIR [RUNS] [BASELINE_GLIDER_DIAGNOSE]
#
# With a baseline binary (e.g. one built at an earlier commit) the two are run alternately, A then B,
# RUNS pairs per case (the load moves both alike), and their outputs compared (--json but wall_s).
set -euo pipefail
build="${1:?usage: diagnose_speed.sh BUILD_DIR [RUNS] [BASELINE_GLIDER_DIAGNOSE]}"
runs="${2:-3}"
baseline="${3:-}"
root="$(cd "$(dirname "$0")/.." && pwd)"
diagnose="$build/tools/science/diagnose/glider-diagnose"
out="$build/benchmark/diagnose_speed"
mkdir -p "$out"
"$build/sil/glider-sil" --mission "$root/boards/missions/day_200m.toml" --out "$out/day_200m.csv" >/dev/null
grep -v 'cd0_reynolds_exponent' "$out/day_200m.csv" >"$out/day_200m_prior.csv"

case_args() {
  case "$1" in
    comet-2016) echo "$root/tests/data/real/comet-2016-174-05.csv --vehicle $root/boards/vehicles/slocum_shallow.toml" ;;
    day_200m) echo "$out/day_200m.csv --plane vertical" ;;
    day_200m_prior) echo "$out/day_200m_prior.csv --plane vertical" ;;
  esac
}

# One run: "user wall" seconds; its --json without wall_s into $3.
one() {
  local binary="$1" name="$2" json="$3"
  # shellcheck disable=SC2046
  /usr/bin/time -o "$out/time" -f '%U %e' "$binary" $(case_args "$name") --json 2>/dev/null |
    sed 's/"wall_s":[^,}]*//g' >"$json"
  tail -n 1 "$out/time"
}

echo "case (goal): user s, wall s per run${baseline:+ (A = baseline $baseline, B = this build, alternating)}"
for name in comet-2016 day_200m day_200m_prior; do
  goal=2
  [ "$name" = comet-2016 ] && goal=5
  line="  $name (< $goal s CPU):"
  for ((i = 1; i <= runs; ++i)); do
    if [ -n "$baseline" ]; then
      a="$(one "$baseline" "$name" "$out/$name.a.json")"
      line+=" A ${a// / s user, } s wall |"
    fi
    b="$(one "$diagnose" "$name" "$out/$name.b.json")"
    line+=" ${baseline:+B }${b// / s user, } s wall;"
  done
  if [ -n "$baseline" ]; then
    if cmp -s "$out/$name.a.json" "$out/$name.b.json"; then line+=" outputs identical"; else line+=" OUTPUTS DIFFER"; fi
  fi
  echo "$line"
done
