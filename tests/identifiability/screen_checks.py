# SPDX-License-Identifier: Apache-2.0
"""A pair not judged must be stated under the screen: shared by the two planes' identifiability tests."""


def stated_under_screen(screen, pair, finding_key, correlation_key):
    """The correlation of `pair` that `screen` (a JSON identifiability_screen) states under its threshold, or None."""
    for p in screen.get("pairs", []):
        c = p[correlation_key]
        if {p[finding_key], p["alternative"]} == pair and c is not None and not p["judged"] \
                and c < screen["screen_correlation"]:
            return c
    return None
