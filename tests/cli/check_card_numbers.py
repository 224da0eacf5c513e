#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Flight test cards refuse bad numbers, with the ranges of glider-sil's options.

The card's numbers (tools/fleet/campaign/cards.py NUMBER_KEYS) become glider-sil's
options: their ranges must be the ones glider-sil --list-numeric-options
prints (the table cannot drift), and every key, and a [[fault]]'s at_s, is
given NaN, +-inf, +-1e308 and values just outside its range: each must be a
CardError naming the key, the value and the allowed range.

Usage: check_card_numbers.py SOURCE_DIR GLIDER_SIL
"""

import copy
import json
import os
import subprocess
import sys
import tomllib


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def main():
    source_dir, sil = sys.argv[1], sys.argv[2]
    sys.path.insert(0, os.path.join(source_dir, "tools", "fleet", "campaign"))
    import cards  # noqa: E402 (the campaign tool's own loader)

    listing = json.loads(subprocess.run([sil, "--list-numeric-options"], capture_output=True, text=True,
                                        timeout=10, check=True).stdout)
    options = {o["name"]: o for o in listing["options"]}
    for key, (low, high, _, integer) in cards.NUMBER_KEYS.items():
        option = options.get("--" + key.replace("_", "-"))
        if option is None:
            fail(f"card key {key}: glider-sil has no number option --{key.replace('_', '-')}")
        if (option["min"], option["max"], option["integer"]) != (low, high, integer):
            fail(f"card key {key}: range [{low}, {high}] (integer {integer}) but glider-sil's "
                 f"{option['name']} is {option['allowed']} (integer {option['integer']})")

    card = os.path.join(source_dir, "tests", "cards", "abort_leak.toml")
    with open(card, "rb") as f:
        base = tomllib.load(f)
    cards.load_setup(base, card)  # the base card itself loads

    def refused(doc, key, value):
        try:
            cards.load_setup(doc, card)
        except cards.CardError as error:
            text = str(error)
            for part in (key, repr(value), "allowed range"):
                if part not in text:
                    fail(f"{key} = {value!r}: the refusal does not name '{part}': {text}")
            return
        fail(f"{key} = {value!r}: accepted")

    tried = 0
    specs = list(cards.NUMBER_KEYS.items()) + [("at_s", cards.FAULT_TIME_RANGE)]
    for key, (low, high, _, integer) in specs:
        values = [float("nan"), float("inf"), float("-inf"), 1e308, -1e308]
        values += [low - 1, high + 1, low + 0.5] if integer else [low - max(abs(low) * 1e-6, 1e-9),
                                                                 high + max(abs(high) * 1e-6, 1e-9)]
        for value in values:
            doc = copy.deepcopy(base)
            if key == "at_s":
                doc["fault"][0]["at_s"] = value
            else:
                doc[key] = value
            refused(doc, key, value)
            tried += 1
    print(f"{tried} bad card numbers refused (keys: {', '.join(k for k, _ in specs)})")
    print("PASS card numbers")
    return 0


if __name__ == "__main__":
    sys.exit(main())
