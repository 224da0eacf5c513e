#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Bad input to glider-forecast, each named by its file, exit 1: an event that
# is not JSON, an event of another glider, a folder with no event, a missing
# mission. Usage: check_bad_input.sh BUILD_DIR SOURCE_DIR OUT_DIR
set -u
build=$1 source=$2 out=$3
bench=$build/tools/shore/forecast/glider-forecast-bench
forecast=$build/tools/shore/forecast/glider-forecast
fail() { echo "FAIL bad_input: $*"; exit 1; }
rm -rf "$out" && mkdir -p "$out" || fail "cannot make $out"
"$bench" --out "$out/bench" --seed 6 --truths 1 --surfacings 2 --from 1 --runs 2 >"$out/bench.txt" 2>&1 ||
  fail "bench: $(cat "$out/bench.txt")"
good=$out/bench/seed6/from1
v=$source/boards/vehicles/slocum_shallow.toml
expect() {  # NAME DIR PATTERN
  "$forecast" --glider-dir "$2" --vehicle "$v" --runs 2 >"$out/$1.txt" 2>&1
  code=$?
  [ $code -eq 1 ] || fail "$1: exit $code, want 1: $(cat "$out/$1.txt")"
  grep -q "$3" "$out/$1.txt" || fail "$1: message does not match '$3': $(cat "$out/$1.txt")"
  echo "ok $1: $(head -1 "$out/$1.txt")"
}
"$forecast" --glider-dir "$good" --vehicle "$v" --runs 2 >"$out/good.txt" 2>&1 || fail "good folder: $(cat "$out/good.txt")"

cp -r "$good" "$out/not_json" && printf '{"schema": "glider-shore-surfacing/1", "glider": ' >"$out/not_json/logs/9999_0001.surfacing.json"
expect not_json "$out/not_json" "not_json/logs/9999_0001.surfacing.json: not JSON"

cp -r "$good" "$out/two_gliders"
sed 's/"simglider"/"otherglider"/' "$good/logs/$(ls "$good/logs" | tail -1)" >"$out/two_gliders/logs/9999_0002.surfacing.json"
expect two_gliders "$out/two_gliders" "9999_0002.surfacing.json: glider 'otherglider'.*two gliders"

cp -r "$good" "$out/bad_time"
sed 's/"call_end_utc": "[^"]*"/"call_end_utc": "yesterday"/' "$good/logs/$(ls "$good/logs" | tail -1)" >"$out/bad_time/logs/9999_0003.surfacing.json"
expect bad_time "$out/bad_time" "9999_0003.surfacing.json: call_end_utc: 'yesterday' is not a UTC time"

mkdir -p "$out/no_events/logs"
expect no_events "$out/no_events" "no_events/logs: no surfacing event with a GPS fix"

cp -r "$good" "$out/no_mission" && rm -r "$out/no_mission/mission"
expect no_mission "$out/no_mission" "no_mission/mission: no mission"

cp -r "$good" "$out/bad_mission"
sed 's/b_arg: overdepth(m)                 60/b_arg: overdepth(m)                 abc/' "$good/mission/missions/box.mi" >"$out/bad_mission/mission/missions/box.mi"
expect bad_mission "$out/bad_mission" "box.mi:[0-9]*"
# The vehicle: without --vehicle and before health has estimates, the glider folder's own vehicle.toml
# (as health reads it); with neither it nor a gliders.toml entry, a refusal that says where to put one.
cp -r "$good" "$out/pilot_vehicle" && rm -rf "$out/pilot_vehicle/health" && cp "$v" "$out/pilot_vehicle/vehicle.toml"
"$forecast" --glider-dir "$out/pilot_vehicle" --runs 2 --json >"$out/pilot_vehicle.json" 2>"$out/pilot_vehicle.txt" ||
  fail "pilot_vehicle: $(cat "$out/pilot_vehicle.txt")"
grep -q '"vehicle": "[^"]*pilot_vehicle/vehicle.toml' "$out/pilot_vehicle.json" ||
  fail "pilot_vehicle: the forecast did not fly GLIDER/vehicle.toml: $(grep '"vehicle"' "$out/pilot_vehicle.json")"
echo "ok pilot_vehicle: GLIDER/vehicle.toml flown"
cp -r "$good" "$out/no_vehicle" && rm -rf "$out/no_vehicle/health" "$out/no_vehicle/vehicle.toml"
"$forecast" --glider-dir "$out/no_vehicle" --runs 2 >"$out/no_vehicle.txt" 2>&1
code=$?
[ $code -eq 1 ] && grep -q "nor vehicle.toml in .*no_vehicle: give --vehicle FILE" "$out/no_vehicle.txt" ||
  fail "no_vehicle: exit $code: $(cat "$out/no_vehicle.txt")"
echo "ok no_vehicle: $(head -1 "$out/no_vehicle.txt")"
# The pilot's prior (GLIDER/forecast.toml, docs/forecast.md "The pilot's prior"): a value out of range,
# NaN, an unknown key or mode, each named by file:line and key; the command line's range-checked too
# (usage, exit 2); a good file is used (the JSON says so) and the command line overrides it.
prior_file() {  # NAME CONTENT PATTERN
  cp -r "$good" "$out/$1" && printf '%b' "$2" >"$out/$1/forecast.toml"
  expect "$1" "$out/$1" "$3"
}
prior_file prior_range '[current_prior]\nm2_sigma_m_s = 3.0\n' "forecast.toml:2: current_prior.m2_sigma_m_s = 3.000000 is outside \\[0.000000, 2.000000\\] m/s"
prior_file prior_nan '[current_prior]\nmode = "fixed"\nmean_sigma_m_s = nan\n' "forecast.toml:3: current_prior.mean_sigma_m_s = nan is outside"
prior_file prior_position_range '[current_prior]\nposition_sigma_m = 6000\n' "forecast.toml:2: current_prior.position_sigma_m = 6000.000000 is outside \\[0.000000, 5000.000000\\] m"
prior_file prior_position_nan '[current_prior]\nposition_sigma_m = nan\n' "forecast.toml:2: current_prior.position_sigma_m = nan is outside"
prior_file prior_key '[current_prior]\ntide = 0.3\n' "forecast.toml:2: current_prior.tide: unknown key"
prior_file prior_mode '[current_prior]\nmode = "maybe"\n' "forecast.toml:2: current_prior.mode: 'maybe' is not a prior mode"
prior_file prior_section '[prior]\nmode = "off"\n' "forecast.toml:1: key 'prior' is not a forecast setting"
"$forecast" --glider-dir "$good" --vehicle "$v" --runs 2 --prior-m2-sigma nan >"$out/prior_cli.txt" 2>&1
code=$?
[ $code -eq 2 ] || fail "prior_cli: --prior-m2-sigma nan: exit $code, want 2: $(cat "$out/prior_cli.txt")"
echo "ok prior_cli: $(head -1 "$out/prior_cli.txt")"
cp -r "$good" "$out/prior_good" && printf '[current_prior]\nmode = "fixed"\nm2_sigma_m_s = 0.05\n' >"$out/prior_good/forecast.toml"
"$forecast" --glider-dir "$out/prior_good" --vehicle "$v" --runs 2 --json >"$out/prior_good.json" 2>&1 ||
  fail "prior_good: $(cat "$out/prior_good.json")"
grep -q '"m2_sigma_m_s": 0.05' "$out/prior_good.json" && grep -q '"mode": "fixed"' "$out/prior_good.json" ||
  fail "prior_good: the file's prior is not in the JSON: $(grep -A8 '"prior"' "$out/prior_good.json")"
"$forecast" --glider-dir "$out/prior_good" --vehicle "$v" --runs 2 --current-prior off --json >"$out/prior_off.json" 2>&1 ||
  fail "prior_off: $(cat "$out/prior_off.json")"
grep -q '"mode": "off"' "$out/prior_off.json" || fail "prior_off: --current-prior off did not override the file"
echo "ok prior_good: GLIDER/forecast.toml used, --current-prior overrides it"
# The pilot's tide table (--tide FILE, docs/forecast.md session 44): NaN, a value out of range, an unknown
# constituent, each named by file:line, key, value and range; fit-tide refuses a record too short for M2.
tide_file() {  # NAME CONTENT PATTERN
  printf '%b' "$2" >"$out/$1.toml"
  "$forecast" --glider-dir "$good" --vehicle "$v" --runs 2 --tide "$out/$1.toml" >"$out/$1.txt" 2>&1
  code=$?
  [ $code -eq 1 ] && grep -q "$3" "$out/$1.txt" || fail "$1: exit $code: $(cat "$out/$1.txt")"
  echo "ok $1: $(head -1 "$out/$1.txt")"
}
m2='[M2]\neast_amplitude_m_s = 0.3\neast_phase_deg = 10\nnorth_amplitude_m_s = 0.1\nnorth_phase_deg = 190\namplitude_sigma_m_s = 0.07\n'
tide_file tide_nan "reference_utc = 2027-01-01T00:00:00Z\n${m2}phase_sigma_deg = nan\n" "tide_nan.toml:8: M2.phase_sigma_deg = nan is outside \\[0, 180\\] deg"
tide_file tide_range "reference_utc = 2027-01-01T00:00:00Z\n${m2}phase_sigma_deg = 30\n[mean]\neast_m_s = 4\n" "tide_range.toml:10: mean.east_m_s = 4 is outside \\[-3, 3\\] m/s"
tide_file tide_name "reference_utc = 2027-01-01T00:00:00Z\n[M3]\n" "tide_name.toml:2: \\[M3\\]: 'M3' is not a tidal constituent"
"$forecast" fit-tide --glider-dir "$good" >"$out/fit_short.txt" 2>&1
code=$?
[ $code -eq 1 ] && grep -q "too short to fit M2: it needs 12.4 h" "$out/fit_short.txt" ||
  fail "fit_short: exit $code: $(cat "$out/fit_short.txt")"
echo "ok fit_short: $(head -1 "$out/fit_short.txt")"
echo "PASS bad_input"
