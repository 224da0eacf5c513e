# SPDX-License-Identifier: Apache-2.0
"""The checks of a lag reading shared by this directory's tests: within 15 % of
the truth, an interval that holds it and is not zero-width."""


def check_interval(failures, seed, low, high, hidden):
    if not low <= hidden <= high:
        failures.append('seed %d: interval [%.2f, %.2f] misses %.2f s' % (seed, low, high, hidden))
    if not high > low:
        failures.append('seed %d: zero-width interval' % seed)


def check_reading(failures, seed, value, low, high, hidden):
    if abs(value - hidden) > 0.15 * hidden:
        failures.append('seed %d: %.2f s is not within 15 %% of %.2f s' % (seed, value, hidden))
    check_interval(failures, seed, low, high, hidden)
