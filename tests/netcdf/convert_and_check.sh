#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# convert_and_check.sh CONVERT CHECK_NC FORMAT OUT METADATA VEHICLE INPUT...: converts
# a deployment to FORMAT (og1: OUT is the file; ioos: OUT is a fresh directory)
# and checks every file written with glider-check-nc; fails on any finding.
set -eu
convert=$1; check=$2; format=$3; out=$4; metadata=$5; vehicle=$6; shift 6
rm -rf "$out"
"$convert" --quiet --format "$format" --metadata "$metadata" --vehicle "$vehicle" --out "$out" "$@"
if [ "$format" = ioos ]; then
  set -- "$out"/*.nc
  [ -e "$1" ] || { echo "FAIL: no IOOS file written"; exit 1; }
else
  set -- "$out"
fi
echo "checking $# file(s)"
"$check" "$@"
