#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Smoke of benchmarks/diagnose_truth_coverage.py: two short draws (a clean
log and one hidden drag change) through glider-truth and glider-diagnose;
checks that both draws ran and that the tables are well formed. It does not
judge the diagnosis (the benchmark's table does)."""
import re
import subprocess
import sys

script, truth, diagnose = sys.argv[1:4]
run = subprocess.run([sys.executable, script, '--truth', truth, '--diagnose', diagnose, '--cases', 'none,drag_change',
                      '--draws', '1', '--jobs', '2', '--yos', '3', '--seed', '26', '--timeout', '100'],
                     capture_output=True, text=True, timeout=110)
print(run.stdout)
print(run.stderr, file=sys.stderr)
failures = []
if run.returncode != 0:
    failures.append('exit %d' % run.returncode)
out = run.stdout
if not re.search(r'^run seed 26 \(2 cases x 1 draws = 2 logs, 2 jobs\)', out, re.M):
    failures.append('no run-seed line')
cases_table = out[:out.find('| effect (singles')]
rows = re.findall(r'^\| (none|drag_change) \| (\d+)( \(\d+ failed\))? \|(.*)\|$', cases_table, re.M)
if len(rows) != 2:
    failures.append('expected the rows of none and drag_change, got %d' % len(rows))
for case, draws, failed, rest in rows:
    if draws != '1' or failed:
        failures.append('%s: %s draws%s' % (case, draws, failed))
    if len(rest.split('|')) != 8:
        failures.append('%s: %d cells after the draws' % (case, len(rest.split('|'))))
if not re.search(r'^\| drag_change \| 1 \| (0|1)/1 \(\d+ %\) \| (0|1)/1', out, re.M):
    failures.append('drag_change row: named/within cells malformed')
if not re.search(r'^\| drag_change \| 1 \| ', out[out.find('| effect (singles'):], re.M):
    failures.append('no per-effect row for drag_change')
if not re.search(r'^speed: one truth log [\d.]+ s median', out, re.M):
    failures.append('no speed line')
if not re.search(r'^replay this run: .* --seed 26 --draws 1 --cases none,drag_change$', out, re.M):
    failures.append('no replay line')
if failures:
    print('FAIL: ' + '; '.join(failures))
    sys.exit(1)
print('PASS truth benchmark smoke')
