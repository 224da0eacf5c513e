#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# The model's own miss on the replayed dives is in the forecast's spread
# (docs/forecast.md): an nsb3.mi SIL truth (3 h dives, seed 11) forecast from
# its 4th surfacing has at least two replayed dives in the last day, says so
# (JSON model_miss, a note), and its 95 % ellipse is at least as wide as that
# miss's larger RMS (the runs are moved by it). Usage: check_model_miss.sh
# BUILD_DIR SOURCE_DIR OUT_DIR
set -u
build=$1 source=$2 out=$3
bench=$build/tools/shore/forecast/glider-forecast-bench
forecast=$build/tools/shore/forecast/glider-forecast
fail() { echo "FAIL model_miss: $*"; exit 1; }
rm -rf "$out" && mkdir -p "$out" || fail "cannot make $out"
"$bench" --out "$out/bench" --seed 11 --truths 1 --surfacings 5 --from 4 --runs 20 --threads 1 \
  --mission "$source/boards/missions/comet-nsb3/missions/nsb3.mi" \
  --vehicle "$source/boards/vehicles/slocum_comet.toml" >"$out/bench.txt" 2>&1 || fail "bench: $(cat "$out/bench.txt")"
json=$out/bench/seed11/from4/forecast/forecast.json
[ -f "$json" ] || fail "no $json: $(cat "$out/bench.txt")"
/usr/bin/python3 - "$json" <<'PY' || exit 1
import json, sys
f = json.load(open(sys.argv[1]))
m, e = f["model_miss"], f["next_surfacing"]["ellipse"]
def fail(why):
    print("FAIL model_miss: " + why + ": " + json.dumps(m) + " " + json.dumps(e))
    sys.exit(1)
if m["dives"] < 2: fail("fewer than 2 replayed dives")
if not any("model's miss" in n for n in f["notes"]): fail("no note of the miss")
if not e["semi_major_m"] >= max(m["rms_east_m"], m["rms_north_m"]): fail("the ellipse is narrower than the miss")
print("PASS model_miss: %d dives, RMS %.0f m E %.0f m N; ellipse %.0f x %.0f m" %
      (m["dives"], m["rms_east_m"], m["rms_north_m"], e["semi_major_m"], e["semi_minor_m"]))
PY
