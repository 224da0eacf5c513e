#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Worst-case blocking of one control cycle on a dead actuator bus, on the
# three dead buses that matter: TCP to a closed port, TCP to a device that
# stopped answering, RTU on a pty with nobody on the other end.
# usage: measure_dead_bus.sh BUILD_DIR [CYCLES]
set -euo pipefail
build="$1"; cycles="${2:-20}"
sim="$build/tools/hardware/actuator_sim/glider-actuator-sim"
dead="$build/tools/hardware/bench/glider-dead-bus"
tmp="$(mktemp -d /tmp/glider-dead-bus.XXXXXX)"
pids=()
cleanup() { for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; wait "$p" 2>/dev/null || true; done; rm -rf "$tmp"; }
trap cleanup EXIT

# A free port, then nobody on it.
"$sim" --tcp 127.0.0.1:0 >"$tmp/free" & p=$!
for _ in $(seq 100); do grep -q serving "$tmp/free" && break; sleep 0.05; done
closed_port="$(sed -n 's/.*serving tcp 127.0.0.1:\([0-9]*\).*/\1/p' "$tmp/free")"
kill "$p"; wait "$p" || true
"$dead" --cycles "$cycles" --tcp "127.0.0.1:$closed_port" --label "TCP, closed port"

"$sim" --tcp 127.0.0.1:0 --fault silent:0 >"$tmp/silent" & pids+=($!)
for _ in $(seq 100); do grep -q serving "$tmp/silent" && break; sleep 0.05; done
port="$(sed -n 's/.*serving tcp 127.0.0.1:\([0-9]*\).*/\1/p' "$tmp/silent")"
"$dead" --cycles "$cycles" --tcp "127.0.0.1:$port" --label "TCP, device stopped answering"

socat pty,raw,echo=0,link="$tmp/device" pty,raw,echo=0,link="$tmp/glider" & pids+=($!)
for _ in $(seq 100); do [ -e "$tmp/glider" ] && break; sleep 0.05; done
"$dead" --cycles "$cycles" --rtu "$tmp/glider" --label "RTU pty, nobody on the other end"
