#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""Tests of tools/fleet/campaign with the real glider-sil: the generator against
splitmix64's published output and pinned draws, run i independent of the
sharding, cards that fail and cards that are refused (table, JUnit XML,
exit status), bad parameters, partial results and the failure ranking.

usage: test_campaign.py GLIDER_SIL GLIDER_DIAGNOSE [unittest arguments]"""

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
TOOL = os.path.join(ROOT, "tools", "fleet", "campaign", "glider_campaign.py")
sys.dont_write_bytecode = True
sys.path.insert(0, os.path.dirname(TOOL))
import campaign  # noqa: E402
import report  # noqa: E402
import sampling  # noqa: E402
import sil_run  # noqa: E402

SIL = None
DIAGNOSE = None
DEMO_SMALL = os.path.join(HERE, "demo_small.toml")


def tool(*args):
    return subprocess.run(["/usr/bin/python3", TOOL, "--sil", SIL, "--diagnose", DIAGNOSE, *args], capture_output=True, text=True,
                          timeout=600, check=False)


class Generator(unittest.TestCase):
    def test_mixer_is_splitmix64(self):
        # splitmix64 from state 0: the first two outputs (Vigna's reference implementation).
        self.assertEqual(sampling.mix64(0), 0xE220A8397B1DCDAF)
        self.assertEqual(sampling.mix64(0x9E3779B97F4A7C15), 0x6E789E6AA1B965F4)

    def test_run_parameters_are_pinned(self):
        # Changing the generator changes every campaign's runs: these values must not move.
        m = campaign.load_campaign(DEMO_SMALL)
        self.assertEqual(sampling.run_seed(m["seed"], 5), 6020183750998930597)
        self.assertEqual(sampling.parameters(m["vary"], m["seed"], 5), {
            "buoyancy.offset_kg": -0.0060912804865376185, "hydrodynamics.cd0": 0.2182788871598648,
            "ballast.rate_m3_s": 2e-05, "current.speed_m_s": 0.2, "current.direction_deg": 90.0,
            "heading.fin_delay_s": 1.374281891823308})

    def test_draws_stay_inside_their_bounds_and_spread(self):
        vary = {"a": {"distribution": "normal", "mean": 0.0, "sigma": 1.0, "min": -0.5, "max": 2.0},
                "b": {"distribution": "uniform", "min": 3.0, "max": 4.0}}
        a = [sampling.parameters(vary, 9, i)["a"] for i in range(2000)]
        b = [sampling.parameters(vary, 9, i)["b"] for i in range(2000)]
        self.assertTrue(all(-0.5 <= x <= 2.0 for x in a))
        self.assertTrue(all(3.0 <= x < 4.0 for x in b))
        self.assertAlmostEqual(sum(b) / len(b), 3.5, delta=0.02)
        self.assertAlmostEqual(sum(1 for x in a if x < 0) / len(a), 0.277, delta=0.03)  # Phi(0)-Phi(-.5) over mass

    def test_grid_walks_every_cell(self):
        vary = {"x": {"grid": [1, 2]}, "y": {"grid": ["p", "q", "r"]}}
        cells = [tuple(sampling.parameters(vary, 1, i).values()) for i in range(6)]
        self.assertEqual(cells, [(1, "p"), (1, "q"), (1, "r"), (2, "p"), (2, "q"), (2, "r")])

    def test_bad_description_names_the_parameter(self):
        with self.assertRaisesRegex(sampling.SpecError, "hydrodynamics.cd0.*min < max"):
            sampling.check_spec("hydrodynamics.cd0", {"distribution": "uniform", "min": 0.3, "max": 0.2})
        with self.assertRaisesRegex(sampling.SpecError, "x.*allowed uniform, normal"):
            sampling.check_spec("x", {"distribution": "lognormal", "mean": 1})


class SummaryJson(unittest.TestCase):
    def test_metrics_from_the_summary_schema(self):
        # docs/sil-summary.md (glider-sil-summary/1): an aborted waypoint run.
        glide = {"settled_samples": 400, "mean_pitch_deg": -26.0, "mean_depth_rate_m_s": 0.23, "pitch_error_samples": 400,
                 "max_pitch_error_deg": 0.6, "rms_pitch_error_deg": 0.2}
        summary = {"schema": "glider-sil-summary/1", "result": "aborted", "stop_reason": None,
                   "abort": {"cause": "leak", "cause_text": "leak detected", "time_s": 600.0, "surfaced_after_s": None,
                             "firmware_knows_surfaced": False, "drop_weight_released": False},
                   "yos": 2, "max_depth_m": 41.5, "segments": 2, "waypoint_list_length": 4, "waypoint_radius_m": 150.0,
                   "waypoints_reached": 1, "waypoints": [{"reached": 1, "time_s": 420.0, "index": 0,
                                                          "true_distance_m": 152.0}],
                   "surfacings": [{"time_s": 300.0, "dr_error_m": 12.0, "dr_distance_m": 700.0, "dr_error_m_per_km": 17.1,
                                   "water_vx_m_s": 0.1, "water_vy_m_s": 0.0}],
                   "dr_error_m_per_km": 17.1, "dr_error_max_m": 12.0, "dives": glide, "climbs": dict(glide, max_pitch_error_deg=1.5),
                   "energy_kj": 3.2, "charge_ah": 0.06, "distance_km": 0.5, "sim_time_s": 700.0, "wall_time_s": 0.01,
                   "cycles": 700, "loop_overruns": 0, "log_rows": 0, "log_rows_lost": 0}
        m = sil_run.metrics_from_summary(summary)
        self.assertEqual((m["result"], m["abort.cause"], m["abort.time_s"]), ("aborted", "leak", 600.0))
        self.assertEqual(m["abort.surfaced_after_s"], float("inf"))  # never surfaced: fails any surfaced_within_s
        self.assertEqual((m["waypoint.1.reached_s"], m["waypoint.1.distance_m"], m["surfacing.1.dr_error_m"]),
                         (420.0, 152.0, 12.0))
        self.assertEqual((m["pitch_error_deg"], m["dives.samples"], m["max_depth_m"]), (1.5, 400, 41.5))
        with self.assertRaisesRegex(sil_run.RunError, "schema"):
            sil_run.metrics_from_summary(dict(summary, schema="glider-sil-summary/2"))


class InTemporaryDirectory(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="glider-campaign-test-")

    def tearDown(self):
        shutil.rmtree(self.dir, ignore_errors=True)


class Campaigns(InTemporaryDirectory):

    def test_run_i_does_not_depend_on_the_sharding(self):
        one, four = os.path.join(self.dir, "one"), os.path.join(self.dir, "four")
        self.assertEqual(tool("run", DEMO_SMALL, "--out", one, "--shards", "1", "--jobs", "1").returncode, 0)
        self.assertEqual(tool("run", DEMO_SMALL, "--out", four, "--shards", "4").returncode, 0)
        with open(os.path.join(one, "report", "results.jsonl")) as f:
            a = f.read()
        with open(os.path.join(four, "report", "results.jsonl")) as f:
            b = f.read()
        self.assertEqual(a.count("\n"), 12)
        self.assertEqual(a, b)
        records = [json.loads(line) for line in a.splitlines()]
        # The varied values reached the flights: the slow pump's runs take longer.
        slow = [r["metrics"]["sim_time_s"] for r in records if r["params"]["ballast.rate_m3_s"] == 1e-05]
        fast = [r["metrics"]["sim_time_s"] for r in records if r["params"]["ballast.rate_m3_s"] == 3e-05]
        self.assertGreater(min(slow), max(fast))
        with open(os.path.join(four, "report", "report.md")) as f:
            text = f.read()
        self.assertIn("## What the failing runs share", text)
        self.assertIn("| ballast.rate_m3_s | `ballast.rate_m3_s <= 2e-05` |", text)

    def test_status_and_report_on_partial_results(self):
        out = os.path.join(self.dir, "partial")
        self.assertEqual(tool("run", DEMO_SMALL, "--out", out, "--shards", "3").returncode, 0)
        os.unlink(os.path.join(out, "shards", "shard-00001.json"))
        status = tool("status", out)
        self.assertIn("2/3 shards, 8/12 runs done", status.stdout)
        self.assertIn("missing shards: 1", status.stdout)
        self.assertEqual(tool("report", out).returncode, 0)
        with open(os.path.join(out, "report", "report.md")) as f:
            self.assertIn("Partial: 2/3 shards, 8/12 runs; missing shards 1", f.read())
        # Running again flies only the missing shard.
        again = tool("run", DEMO_SMALL, "--out", out, "--shards", "3")
        self.assertIn("1 to fly (4 runs)", again.stderr)

    def test_another_campaign_is_not_mixed_into_a_results_directory(self):
        out = os.path.join(self.dir, "mixed")
        self.assertEqual(tool("run", DEMO_SMALL, "--out", out, "--first", "2").returncode, 0)
        other = tool("run", DEMO_SMALL, "--out", out, "--shards", "2")
        self.assertEqual(other.returncode, 2)
        self.assertIn("holds results of another campaign or sharding", other.stderr)

    def test_a_bad_campaign_file_exits_1_and_a_usage_error_2(self):
        # README's exit codes: bad input (the file's runs = 0) is 1; a missing argument is 2.
        path = os.path.join(self.dir, "zero_runs.toml")
        with open(DEMO_SMALL) as f:
            text = f.read()
        self.assertRegex(text, r"(?m)^runs = [0-9]+$")
        with open(path, "w") as f:
            f.write(re.sub(r"(?m)^runs = [0-9]+$", "runs = 0", text).replace("../../boards", os.path.join(ROOT, "boards")))
        bad = tool("run", path, "--out", os.path.join(self.dir, "zero_runs"))
        self.assertEqual(bad.returncode, 1, bad.stderr)
        self.assertIn("runs = 0: must be an integer >= 1", bad.stderr)
        self.assertEqual(tool("fleet", "status").returncode, 2)

    def test_a_bad_vehicle_key_is_a_run_that_could_not_fly(self):
        path = os.path.join(self.dir, "typo.toml")
        with open(DEMO_SMALL) as f:
            text = f.read().replace('"hydrodynamics.cd0"', '"hydrodynamics.cd00"').replace(
                "../../boards", os.path.join(ROOT, "boards"))
        with open(path, "w") as f:
            f.write(text)
        out = os.path.join(self.dir, "typo")
        self.assertEqual(tool("run", path, "--out", out, "--first", "1").returncode, 0)
        with open(os.path.join(out, "report", "results.jsonl")) as f:
            record = json.loads(f.readline())
        self.assertEqual(record["metrics"]["result"], "error")
        self.assertIn("cd00", record["error"])
        self.assertFalse(record["passed"])

    def test_ranking_finds_the_parameter_that_explains_the_failures(self):
        records = [{"run": i, "passed": not (i % 10 >= 7), "params": {"x": (i % 10) / 10.0, "y": (i * 7919) % 13}}
                   for i in range(100)]
        ranking = report.rank_parameters(records)
        self.assertEqual(ranking[0]["parameter"], "x")
        self.assertEqual(ranking[0]["rule"], "x > 0.6")
        self.assertEqual((ranking[0]["failing_in_rule"], ranking[0]["runs_in_rule"]), (30, 30))
        self.assertAlmostEqual(ranking[0]["share_of_failures"], 1.0)
        self.assertLess(ranking[1]["gain_bits"], 0.1)


class Fleet(InTemporaryDirectory):
    def test_two_deployments_of_one_glider_and_a_log_that_cannot_be_read(self):
        real = os.path.join(ROOT, "tests", "data", "real")
        logs = [os.path.join(real, f) for f in ("comet-2019-222-02-154.csv", "gliderflight-adcp.csv")]
        out = os.path.join(self.dir, "fleet")
        proc = tool("fleet", "run", *logs, "--vehicle", os.path.join(ROOT, "boards", "vehicles", "slocum_we01.toml"),
                    "--out", out, "--shards", "2")
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertIn("| comet | 2 (1 failed) | drag_change x1 |", proc.stdout)
        self.assertRegex(proc.stdout, r"\| comet \| comet-2019-222-02-154 \| [0-9]+ \| drag_change \| [0-9.]+ \| [0-9.]+ \|")
        # gliderflight's file needs column renames (./glider diagnose-real gives them): reported, not dropped.
        self.assertIn("| comet | gliderflight-adcp | | FAILED: glider-diagnose: ", proc.stdout)
        self.assertTrue(os.path.exists(os.path.join(out, "report", "rms.png")))


class Cards(InTemporaryDirectory):
    def card(self, name, expect, extra=""):
        path = os.path.join(self.dir, name + ".toml")
        with open(path, "w") as f:
            f.write(f'mission = "{ROOT}/boards/missions/demo_yo.toml"\n'
                    f'vehicle = "{ROOT}/boards/vehicles/slocum_we01.toml"\n{extra}\n[expect]\n{expect}\n')
        return path

    def regress(self, *paths):
        """./glider regress of the cards: (process, JUnit testsuite element)."""
        junit = os.path.join(self.dir, "junit.xml")
        return tool("regress", *paths, "--junit", junit), ET.parse(junit).getroot()

    def test_a_failing_expectation_fails_the_run_with_its_measured_value(self):
        good = self.card("good", 'result = "complete"\nyos = 3')
        bad = self.card("bad", 'result = "complete"\nenergy.max_kj = 0.5\nwaypoint.1.reached_before_s = 10')
        proc, suite = self.regress(good, bad)
        self.assertEqual(proc.returncode, 1)
        self.assertRegex(proc.stdout, r"bad +energy.max_kj = 0.5 +energy_kj = [0-9.]+ +FAIL")
        self.assertRegex(proc.stdout, r"bad +waypoint.1.reached_before_s = 10 +waypoint.1.reached_s: not reached +FAIL")
        self.assertRegex(proc.stdout, r"good +yos = 3 +yos = 3 +pass")
        self.assertEqual((suite.get("tests"), suite.get("failures"), suite.get("errors")), ("5", "2", "0"))
        failure = suite.find(".//testcase[@name='energy.max_kj = 0.5']/failure")
        self.assertIn("energy_kj = ", failure.get("message"))

    def test_faults_and_fixed_settings_reach_the_flight(self):
        leak = self.card("leak", 'result = "aborted"\nabort.cause = "leak"\nabort.time_s = { min = 300, max = 302 }',
                         '[set]\n"buoyancy.offset_kg" = 0.02\n[[fault]]\nname = "leak"\nat_s = 300')
        proc = tool("regress", leak)
        self.assertEqual(proc.returncode, 0, proc.stdout + proc.stderr)

    def test_a_bad_card_is_refused_with_file_and_key(self):
        typo = self.card("typo", "depth.maxm = 3")
        bad_result = self.card("result", 'result = "finished"')
        proc, suite = self.regress(typo, bad_result)
        self.assertEqual(proc.returncode, 1)
        self.assertIn(f"{typo}: [expect] depth.maxm: unknown metric 'depth.maxm'", proc.stderr)
        self.assertIn("result = 'finished': allowed complete, aborted, stopped", proc.stderr)
        self.assertEqual(suite.get("errors"), "2")


if __name__ == "__main__":
    SIL = os.path.abspath(sys.argv.pop(1))
    DIAGNOSE = os.path.abspath(sys.argv.pop(1))
    unittest.main()
