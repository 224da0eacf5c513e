#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# glider-bench end to end against glider-actuator-sim (TCP loopback, a free
# port): status, a refused target, no confirmation, a move with CSV log, a
# step response, and the error when no device answers.
# usage: bench_cli.sh BUILD_DIR
set -euo pipefail
build="$1"
bench="$build/tools/hardware/bench/glider-bench"
tmp="$(mktemp -d /tmp/glider-bench-cli.XXXXXX)"
sim_pid=""
cleanup() { [ -n "$sim_pid" ] && { kill "$sim_pid" 2>/dev/null; wait "$sim_pid" 2>/dev/null; }; rm -rf "$tmp"; }
trap cleanup EXIT
fail() { echo "FAIL: $*"; exit 1; }
expect() {  # expect EXIT_CODE PATTERN -- COMMAND...
  local code="$1" pattern="$2"; shift 3
  local out rc=0
  out="$("$@" 2>&1 </dev/null)" || rc=$?
  printf '$ %s\n%s\n' "$*" "$out"
  [ "$rc" -eq "$code" ] || fail "exit code $rc, expected $code"
  grep -Eq -- "$pattern" <<<"$out" || fail "output does not match: $pattern"
}

"$build/tools/hardware/actuator_sim/glider-actuator-sim" --tcp 127.0.0.1:0 --time-scale 20 >"$tmp/sim" & sim_pid=$!
for _ in $(seq 100); do grep -q serving "$tmp/sim" && break; sleep 0.05; done
port="$(sed -n 's/.*serving tcp 127.0.0.1:\([0-9]*\).*/\1/p' "$tmp/sim")"
at=(--tcp "127.0.0.1:$port")

expect 0 "pump   : slave 1 @0: glider actuator map v1.0; \+0.000 cc" -- "$bench" "${at[@]}" status
expect 2 "refused: 300 cc is outside the pump's limits \[-250, 250\] cc" -- "$bench" "${at[@]}" --yes move pump 300
expect 2 "not confirmed: nothing moved" -- "$bench" "${at[@]}" move pump 100
expect 0 "pump move \+0.000 -> \+100.000 cc: arrived" -- "$bench" "${at[@]}" --yes --csv "$tmp/move.csv" move pump 100
sed -n 2p "$tmp/move.csv" | grep -q "^time_s,axis,target,position,speed,status,fault_code$" || fail "CSV header"
[ "$(wc -l <"$tmp/move.csv")" -ge 4 ] || fail "CSV has no samples"
rows="$(grep -vc '^#' "$tmp/move.csv")"
tail -1 "$tmp/move.csv" | grep -q "^# end: complete rows=$((rows - 1)) lost=0$" || fail "CSV trailer: $(tail -1 "$tmp/move.csv")"
expect 0 "slide step \+0.000 -> \+0.200 in: arrived.*overshoot 0.0 %" -- "$bench" "${at[@]}" --yes step slide 0.2
expect 0 "pump   : .*\+100.000 cc" -- "$bench" "${at[@]}" status
kill "$sim_pid"; wait "$sim_pid" 2>/dev/null || true; sim_pid=""
expect 1 "no device answers at tcp 127.0.0.1:$port" -- "$bench" "${at[@]}" status
echo PASS
