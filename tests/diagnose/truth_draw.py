# SPDX-License-Identifier: Apache-2.0
"""One draw of the independent truth, diagnosed as a black box: the one way the tests fly a log of the truth
simulator (tools/science/truth, glider-truth) with hidden effects, pick the vehicle file its variant flies, and read
glider-diagnose's JSON on it (tests/ambiguous_beside, tests/density_from_start, tests/depth_lag_form,
tests/diagnose_intervals, tests/diagnose_pump_lag, tests/heading_plane, tests/identifiability,
tests/lift_velocity_misses, tests/offset_misses, tests/reynolds_drag, tests/reynolds_prior_interval,
tests/unnamed_volume_terms, tests/vertical_coverage, tests/zero_width; benchmarks/diagnose_truth_coverage.py flies its
draws with run_truth).

A script puts this directory on its path and imports it:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'diagnose'))
    from truth_draw import fly_and_diagnose  # noqa: E402
"""
import json
import os
import random
import subprocess
import sys

# The vehicle file each of the truth's variants flies (boards/vehicles): its nominal polar and hull.
VEHICLE_OF_VARIANT = {'shallow': 'slocum_shallow.toml', 'deep': 'slocum_we01.toml'}


def fresh_seed(upper=2**31):
    """A fresh seed each run, from the system's entropy, in [1, upper); GLIDER_TEST_SEED=N replays the draw of seed
    N. The caller prints the seed it drew, so a failure can be replayed."""
    return int(os.environ.get('GLIDER_TEST_SEED') or random.SystemRandom().randrange(1, upper))


def vehicle_file(vehicles, variant):
    """The vehicle file the truth's `variant` flies, in the directory `vehicles` (a checkout's boards/vehicles)."""
    return os.path.join(vehicles, VEHICLE_OF_VARIANT[variant])


def truth_command(truth, variant, seed, effects, log, truth_json=None, yos=6, value_format='%.9g'):
    """glider-truth's command line: `yos` yos (None: the truth's default), the truth's JSON when asked, the hidden
    `effects` {id: value}, each value written with `value_format` (the digits a test has always drawn with)."""
    command = [truth, '--variant', variant, '--seed', str(seed)]
    if yos is not None:
        command += ['--yos', str(yos)]
    command += ['--out', log]
    if truth_json:
        command += ['--truth', truth_json]
    for effect, value in effects.items():
        command += ['--effect', ('%s=' + value_format) % (effect, value)]
    return command


def run_truth(truth, variant, seed, effects, log, truth_json=None, yos=6, value_format='%.9g', timeout=120):
    """glider-truth on truth_command's arguments: the finished run (its exit code and message are the caller's to
    judge; fly fails the test on a failed flight)."""
    return subprocess.run(truth_command(truth, variant, seed, effects, log, truth_json, yos, value_format),
                          capture_output=True, text=True, timeout=timeout)


def fly(*args, **kwargs):
    """Write the truth's log (and its JSON when asked) with the hidden `effects` {id: value}: run_truth's
    arguments. A failed flight fails the test, naming its command line and the end of its message."""
    made = run_truth(*args, **kwargs)
    if made.returncode != 0:
        sys.exit('FAIL glider-truth exit %d (%s): %s' % (made.returncode, ' '.join(made.args),
                                                         made.stderr.strip()[-300:]))


def diagnose_log(program, log, vehicle, extra=(), plane='vertical', timeout=120):
    """glider-diagnose's `plane` on `log` (`extra`: more arguments, e.g. --fit): its JSON.
    A failed run fails the test, naming the exit code and the end of its message."""
    run = subprocess.run([program, log, '--vehicle', vehicle, '--plane', plane, '--json', *extra],
                         capture_output=True, text=True, timeout=timeout)
    if run.returncode != 0:
        sys.exit('FAIL glider-diagnose exit %d on %s: %s' % (run.returncode, log, run.stderr[-300:]))
    return json.loads(run.stdout)


def fly_and_diagnose(truth, program, vehicle, out, name, variant, seed, effects):
    """The draw's log (OUT/NAME_SEED.csv, its truth beside it as .json), diagnosed: the JSON."""
    log = os.path.join(out, '%s_%d.csv' % (name, seed))
    fly(truth, variant, seed, effects, log, truth_json=os.path.join(out, '%s_%d.json' % (name, seed)))
    return diagnose_log(program, log, vehicle)


def findings(document):
    """The JSON's findings by effect id."""
    return {f['effect']: f for f in document['findings']}


def heading_findings(document):
    """The heading plane's findings of every link by effect id."""
    found = {}
    for link in (document.get('heading') or {}).get('links', {}).values():
        for f in link.get('findings', []) or []:
            found[f['effect']] = f
    return found
