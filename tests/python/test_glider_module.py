# SPDX-License-Identifier: Apache-2.0
"""`import glider`: the log reader (CSV and Slocum binaries) as numpy arrays,
the steady-glide and time-domain models, and diagnose() returning what
`glider-diagnose --json` prints. Run by CTest (python.glider_module) with the
built module on PYTHONPATH and GLIDER_DIAGNOSE naming the CLI."""
import json
import math
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import glider

ROOT = Path(__file__).resolve().parents[2]
REAL = ROOT / "tests" / "data" / "real"
SEGMENT_154 = [REAL / "dbd" / "comet-2019" / f"comet-2019-222-02-154.{ext}" for ext in ("dbd", "ebd")]
VEHICLE = ROOT / "boards" / "vehicles" / "slocum_we01.toml"


def test_binary_and_csv_logs_read_as_numpy_arrays():
    binary = glider.read_log(SEGMENT_154)
    csv = glider.read_log(REAL / "comet-2019-222-02-154.csv")
    assert len(binary) == len(csv) == 2243
    assert binary.columns[0] == "m_present_time"
    for name in csv.columns:
        a, b = binary[name], csv[name]
        assert a.dtype == np.float64 and a.shape == (2243,)
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        ok = ~np.isnan(b)
        # The CSV holds 7 significant digits (10 us for the time).
        assert np.allclose(a[ok], b[ok], rtol=1e-6, atol=1e-5), name
    assert "m_time_til_wpt" in binary and "m_time_til_wpt" not in csv
    assert any("m_time_til_wpt" in w for w in binary.warnings)  # its -inf values, with file and byte offset


def test_a_directory_and_selected_columns():
    log = glider.read_log(REAL / "dbd" / "comet-2016", columns=["m_depth", "sci_water_temp"])
    assert log.columns == ["m_present_time", "m_depth", "sci_water_temp"]
    assert len(log) == 3043
    assert np.all(np.diff(log.time) > 0)
    temperature = log["sci_water_temp"]
    assert 5.0 < np.nanmin(temperature) < 6.0 and 17.0 < np.nanmax(temperature) < 18.0


def test_bad_input_is_an_error_naming_the_file():
    with pytest.raises(Exception, match="no-such-dir"):
        glider.read_log("/tmp/no-such-dir/x.dbd")
    with pytest.raises(KeyError):
        glider.read_log(SEGMENT_154)["not_a_sensor"]


def test_steady_glide_dives_heavy_and_climbs_light():
    vehicle = glider.load_vehicle(VEHICLE)
    pitch = np.radians([-25.0, 25.0, 1.0])
    buoyancy = np.array([0.2, -0.2, 0.2])  # kg, + heavy
    glide = glider.steady_glide(vehicle, pitch, buoyancy)
    assert glide["depth_rate_m_s"][0] > 0.05  # a dive sinks
    assert glide["depth_rate_m_s"][1] < -0.05  # a climb rises
    assert 0.1 < glide["speed_m_s"][0] < 1.0
    assert math.isnan(glide["speed_m_s"][2])  # no steady glide nose up while heavy at 1 deg


def test_time_domain_and_steady_models_track_the_measured_depth_rate():
    log = glider.read_log(SEGMENT_154)
    for model in ("steady", "dynamic"):
        out = glider.model_depth_rate(log, VEHICLE, model=model)
        ok = ~np.isnan(out["model_m_s"])
        assert ok.sum() > 1000, model
        # Dives down, climbs up, in the model as in the measurement.
        agree = np.sign(out["model_m_s"][ok]) == np.sign(out["measured_m_s"][ok])
        assert agree.mean() > 0.95, model


def test_diagnose_returns_what_the_cli_prints():
    cli = os.environ.get("GLIDER_DIAGNOSE")
    if not cli:
        pytest.skip("GLIDER_DIAGNOSE not set (run through CTest)")
    args = [cli, *map(str, SEGMENT_154), "--vehicle", str(VEHICLE), "--model", "steady", "--json"]
    want = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    got = glider.diagnose(glider.read_log(SEGMENT_154), vehicle=str(VEHICLE), model="steady")
    want.pop("wall_s")
    got.pop("wall_s")
    assert got == want
