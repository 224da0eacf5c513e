#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""TEST FIXTURE standing in for `glider-forecast rehearse` (CONTRACTS.md) in
the console's security test: `rehearse --glider-dir DIR FILE --json`; a file
whose name has "abort" in it gets verdict aborts (exit 4), one with "bad"
verdict refused (exit 1), any other ok (exit 0)."""
import json
import os
import sys

args = sys.argv[1:]
if len(args) < 4 or args[0] != "rehearse" or args[1] != "--glider-dir":
    sys.exit(2)
name = os.path.basename(args[3])
verdict, code = ("aborts", 4) if "abort" in name else (("refused", 1) if "bad" in name else ("ok", 0))
print(json.dumps({"schema": "glider-rehearsal/1", "glider": os.path.basename(args[2]), "file": name,
                  "verdict": verdict, "message": "fixture rehearsal: " + verdict, "abort_risk": 0.9 if code == 4 else 0.0,
                  "abort_causes": {"MS_ABORT_OVERDEPTH": 0.9} if code == 4 else {}}))
sys.exit(code)
