#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Rehearse before send (docs/forecast.md): on a glider folder made from a SIL
# truth (box.mi, two surfacings), `glider-shore queue` refuses a goto_l10.ma
# whose first waypoint lies beyond the mission's max_wpt_distance (the
# rehearsal aborts: waypoint_too_far) and queues it with --force (journaled);
# `glider-forecast rehearse` exits 4 on it, 1 on a yo10.ma the loader refuses
# (a dive beyond the rating, file:line named), 0 on a harmless change.
# Usage: check_rehearse.sh BUILD_DIR SOURCE_DIR OUT_DIR
set -u
build=$1 source=$2 out=$3
bench=$build/tools/shore/forecast/glider-forecast-bench
forecast=$build/tools/shore/forecast/glider-forecast
shore=$build/tools/shore/station/glider-shore
fail() { echo "FAIL rehearse: $*"; exit 1; }
rm -rf "$out" && mkdir -p "$out/root" "$out/files" || fail "cannot make $out"
"$bench" --out "$out/bench" --seed 5 --truths 1 --surfacings 2 --from 1 --runs 5 >"$out/bench.txt" 2>&1 ||
  fail "bench: $(cat "$out/bench.txt")"
mv "$out/bench/seed5/from1" "$out/root/simglider" || fail "no glider folder"
mkdir -p "$out/root/simglider/health" &&
  cp "$source/boards/vehicles/slocum_shallow.toml" "$out/root/simglider/health/vehicle.toml" || fail "vehicle"
g=$out/root/simglider
cp "$source/tests/forecast/data/goto_l10_far.ma" "$out/files/goto_l10.ma"
mkdir -p "$out/files/deep" "$out/files/ok"
cp "$source/tests/forecast/data/yo10_deep.ma" "$out/files/deep/yo10.ma"
cp "$source/tests/forecast/data/goto_l10_ok.ma" "$out/files/ok/goto_l10.ma"

"$forecast" rehearse --glider-dir "$g" "$out/files/goto_l10.ma" --runs 20 >"$out/far.txt" 2>&1
code=$?
[ $code -eq 4 ] || fail "rehearse far waypoint: exit $code, want 4: $(cat "$out/far.txt")"
grep -q "waypoint_too_far" "$out/far.txt" || fail "rehearse far waypoint: cause not named: $(cat "$out/far.txt")"
[ -f "$g/forecast/rehearsals/goto_l10.ma.json" ] || fail "no rehearsals/goto_l10.ma.json"
grep -q '"verdict": "aborts"' "$g/forecast/rehearsals/goto_l10.ma.json" || fail "rehearsal json verdict"

"$forecast" rehearse --glider-dir "$g" "$out/files/deep/yo10.ma" --runs 5 >"$out/deep.txt" 2>&1
code=$?
[ $code -eq 1 ] || fail "rehearse deep yo: exit $code, want 1: $(cat "$out/deep.txt")"
grep -q "yo10.ma: .*beyond the vehicle.s rating" "$out/deep.txt" || fail "deep yo: loader message not named: $(cat "$out/deep.txt")"

"$forecast" rehearse --glider-dir "$g" "$out/files/ok/goto_l10.ma" --runs 20 >"$out/ok.txt" 2>&1
code=$?
[ $code -eq 0 ] || fail "rehearse harmless change: exit $code, want 0: $(cat "$out/ok.txt")"

"$shore" queue --root "$out/root" simglider "$out/files/goto_l10.ma" >"$out/queue.txt" 2>&1
code=$?
[ $code -eq 1 ] || fail "shore queue of the aborting .ma: exit $code, want 1: $(cat "$out/queue.txt")"
grep -q "not queued: aborts" "$out/queue.txt" || fail "queue refusal message: $(cat "$out/queue.txt")"
[ ! -e "$g/to-glider/goto_l10.ma" ] || fail "refused file was queued"

"$shore" queue --root "$out/root" simglider "$out/files/deep/yo10.ma" >"$out/queue_deep.txt" 2>&1
code=$?
[ $code -eq 1 ] || fail "shore queue of the refused .ma: exit $code: $(cat "$out/queue_deep.txt")"
grep -q "not queued: refused" "$out/queue_deep.txt" || fail "queue deep message: $(cat "$out/queue_deep.txt")"

"$shore" queue --root "$out/root" simglider "$out/files/goto_l10.ma" --force >"$out/force.txt" 2>&1 ||
  fail "shore queue --force: $(cat "$out/force.txt")"
[ -f "$g/to-glider/goto_l10.ma" ] || fail "--force did not queue"
grep -q "queued goto_l10.ma with --force: aborts" "$g/logs/queue.journal" || fail "--force not journaled"
echo "PASS rehearse"
