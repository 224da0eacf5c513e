#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# expect.sh CODE PATTERN -- COMMAND...: passes when COMMAND exits with CODE and
# its output (stdout and stderr, as one text: . matches newlines) matches the extended regular expression PATTERN.
code=$1; pattern=$2; shift 3
out=$("$@" 2>&1); rc=$?
printf '%s\n' "$out"
[ "$rc" -eq "$code" ] || { echo "FAIL: exit $rc, expected $code"; exit 1; }
printf '%s\n' "$out" | grep -Ezq -- "$pattern" || { echo "FAIL: output does not match: $pattern"; exit 1; }
echo "PASS"
