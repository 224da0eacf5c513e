# SPDX-License-Identifier: Apache-2.0
"""One draw of the independent truth, diagnosed as a black box: the step the
vertical plane's truth-draw tests share (tests/density_from_start,
tests/diagnose_intervals, tests/diagnose_pump_lag, tests/reynolds_drag,
tests/reynolds_prior_interval, tests/zero_width).

A script puts this directory on its path and imports it:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
    from truth_draw import fly_and_diagnose  # noqa: E402
"""
import json
import os
import subprocess
import sys


def fly(truth, variant, seed, effects, log, truth_json=None, yos=6):
    """Write the truth's log of `yos` yos (and its JSON when asked) with the hidden `effects` {id: value}."""
    command = [truth, '--variant', variant, '--seed', str(seed), '--yos', str(yos), '--out', log]
    if truth_json:
        command += ['--truth', truth_json]
    for effect, value in effects.items():
        command += ['--effect', '%s=%.9g' % (effect, value)]
    subprocess.run(command, check=True, capture_output=True, timeout=120)


def diagnose_log(program, log, vehicle, extra=()):
    """glider-diagnose's vertical plane on `log` (`extra`: more arguments, e.g. --fit): its JSON.
    A failed run fails the test, naming the exit code and the end of its message."""
    run = subprocess.run([program, log, '--vehicle', vehicle, '--plane', 'vertical', '--json', *extra],
                         capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        sys.exit('FAIL glider-diagnose exit %d: %s' % (run.returncode, run.stderr[-300:]))
    return json.loads(run.stdout)


def fly_and_diagnose(truth, program, vehicle, out, name, variant, seed, effects):
    """The draw's log (OUT/NAME_SEED.csv, its truth beside it as .json), diagnosed: the JSON."""
    log = os.path.join(out, '%s_%d.csv' % (name, seed))
    fly(truth, variant, seed, effects, log, truth_json=os.path.join(out, '%s_%d.json' % (name, seed)))
    return diagnose_log(program, log, vehicle)


def findings(document):
    """The JSON's findings by effect id."""
    return {f['effect']: f for f in document['findings']}
