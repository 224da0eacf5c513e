# SPDX-License-Identifier: Apache-2.0
"""./glider regress: fly every flight test card in parallel, print a table
of every expectation with its measured value, write JUnit XML."""

import concurrent.futures
import os
import sys
import xml.etree.ElementTree as ET

import cards
import sil_run


def find_cards(arguments):
    """Card files from directories (every *.toml in them, sorted) and files."""
    paths = []
    for argument in arguments:
        if os.path.isdir(argument):
            paths += sorted(os.path.join(argument, f) for f in os.listdir(argument) if f.endswith(".toml"))
        else:
            paths.append(argument)
    return paths


def fly_card(sil_binary, card):
    metrics, cost, error = sil_run.fly(sil_binary, card, dict(card["set"]), card["seed"])
    return {"card": card, "rows": cards.check(card["expect"], metrics, error), "wall_s": cost["wall_s"],
            "error": error}


def write_junit(results, broken, path):
    suite = ET.Element("testsuite", name="glider.regress")
    tests = failures = errors = 0
    for path_, why in broken:
        case = ET.SubElement(suite, "testcase", classname="glider.regress", name=os.path.basename(path_))
        ET.SubElement(case, "error", message=why).text = why
        tests += 1
        errors += 1
    for r in results:
        name = r["card"]["name"]
        for text, measured, passed in r["rows"]:
            case = ET.SubElement(suite, "testcase", classname=f"glider.regress.{name}", name=text,
                                 time=f"{r['wall_s'] / max(1, len(r['rows'])):.3f}")
            ET.SubElement(case, "system-out").text = measured
            tests += 1
            if not passed:
                failures += 1
                ET.SubElement(case, "failure", message=f"{text}: measured {measured}").text = measured
    suite.set("tests", str(tests))
    suite.set("failures", str(failures))
    suite.set("errors", str(errors))
    ET.indent(suite)
    # docs/campaigns.md's `--junit build/cards.xml` on a fresh clone: make the folder, as --out does.
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    ET.ElementTree(suite).write(path, encoding="utf-8", xml_declaration=True)


def print_table(results, out):
    rows = [("card", "expectation", "measured", "result")]
    for r in results:
        for text, measured, passed in r["rows"]:
            rows.append((r["card"]["name"], text, measured, "pass" if passed else "FAIL"))
    widths = [max(len(row[i]) for row in rows) for i in range(3)]
    for row in rows:
        out.write(f"{row[0]:<{widths[0]}}  {row[1]:<{widths[1]}}  {row[2]:<{widths[2]}}  {row[3]}\n")


def run(arguments, sil_binary, junit_path, jobs):
    paths = find_cards(arguments)
    if not paths:
        print("glider regress: no card files given or found", file=sys.stderr)
        return 2
    loaded, broken = [], []
    for path in paths:
        try:
            loaded.append(cards.load_card(path))
        except cards.CardError as error:
            broken.append((path, str(error)))
            print(f"glider regress: {error}", file=sys.stderr)
    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        results = list(pool.map(lambda card: fly_card(sil_binary, card), loaded))
    print_table(results, sys.stdout)
    checked = sum(len(r["rows"]) for r in results)
    failed = sum(1 for r in results for _, _, passed in r["rows"] if not passed)
    wall = sum(r["wall_s"] for r in results)
    print(f"\n{len(results)} cards, {checked} expectations: {checked - failed} passed, {failed} failed"
          f"{f', {len(broken)} card files refused' if broken else ''} ({wall:.1f} s of flights on {jobs} workers)")
    if junit_path:
        write_junit(results, broken, junit_path)
        print(f"JUnit XML: {junit_path}")
    return 1 if failed or broken else 0
