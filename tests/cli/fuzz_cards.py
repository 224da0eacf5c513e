#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""Flight test cards on arbitrary content: every shipped card, mutated.

A seeded random walk over the cards of tests/cards: keys set to values of
every type (NaN, inf, huge and negative numbers, strings, lists, tables,
booleans), keys deleted, tables emptied. load_card's contract is that a bad
card is a CardError naming what is wrong; any other exception (TypeError,
AttributeError...) is a bug. Bounded by a case count, seeded: a failure
prints the seed and the card that broke it.

Usage: fuzz_cards.py SOURCE_DIR [CASES] [SEED]
"""

import copy
import glob
import math
import os
import random
import sys
import tempfile

VALUES = [float("nan"), float("inf"), float("-inf"), 1e308, -1e308, 0, -1, 2**63, 2**64, 0.5, True, "", "x",
          "../../boards/vehicles/slocum_we01.toml", [], [1], [{}], {}, {"min": 1}, {"name": "leak"},
          {"name": "leak", "at_s": "x"}, {"name": 3, "at_s": 1}, {"nested": {"deeper": float("nan")}}]


def mutate(doc, rng):
    """One to three random changes, at the top level or one table down."""
    for _ in range(rng.randint(1, 3)):
        table = doc
        keys = list(table.keys())
        if keys and rng.random() < 0.4:
            inner = table[rng.choice(keys)]
            if isinstance(inner, dict):
                table = inner
            elif isinstance(inner, list) and inner and isinstance(inner[0], dict):
                table = inner[0]
        keys = list(table.keys())
        action = rng.random()
        if keys and action < 0.2:
            del table[rng.choice(keys)]
        elif keys and action < 0.8:
            table[rng.choice(keys)] = copy.deepcopy(rng.choice(VALUES))
        else:
            table[rng.choice(["seed", "legs", "fault", "expect", "set", "heading_deg", "zzz", "max_sim_time_s"])] = \
                copy.deepcopy(rng.choice(VALUES))


def main():
    source = sys.argv[1]
    cases = int(sys.argv[2]) if len(sys.argv) > 2 else 3000
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 20261127
    sys.path.insert(0, os.path.join(source, "tools", "fleet", "campaign"))
    import cards  # noqa: E402
    import tomllib  # noqa: E402

    paths = sorted(glob.glob(os.path.join(source, "tests", "cards", "*.toml")))
    bases = []
    for path in paths:
        with open(path, "rb") as f:
            bases.append((path, tomllib.load(f)))
    rng = random.Random(seed)
    refused = accepted = 0
    for case in range(cases):
        path, base = rng.choice(bases)
        doc = copy.deepcopy(base)
        mutate(doc, rng)
        try:
            setup = cards.load_setup(doc, path)
            if "expect" not in doc or not doc["expect"]:
                raise cards.CardError("no [expect]")
            setup["expect"] = cards.parse_expectations(doc["expect"], path)
            accepted += 1
            for key in cards.NUMBER_KEYS:
                if key in setup and not (isinstance(setup[key], (int, float)) and math.isfinite(setup[key])):
                    print(f"FAIL: case {case} (seed {seed}): {key} = {setup[key]!r} accepted from {path}: {doc!r}")
                    return 1
        except cards.CardError:
            refused += 1
        except Exception as error:  # noqa: BLE001 (any other exception is the bug this looks for)
            print(f"FAIL: case {case} (seed {seed}): {type(error).__name__}: {error} from {path}: {doc!r}")
            return 1
    print(f"{cases} mutated cards of {len(bases)}: {refused} refused (CardError), {accepted} accepted")
    print("PASS fuzz cards")
    return 0


if __name__ == "__main__":
    sys.exit(main())
