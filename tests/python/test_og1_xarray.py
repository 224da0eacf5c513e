# SPDX-License-Identifier: Apache-2.0
"""glider.read_log(...) as an xarray Dataset in the OG1.0 layout and as a
pandas DataFrame, OG1.0 files read back, science-only files (docs/python.md).
Run by CTest (python.og1_xarray) with the built module on PYTHONPATH and
GLIDER_CONVERT naming the CLI; xarray, pandas and netCDF4 from Debian."""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import xarray as xr

import glider

ROOT = Path(__file__).resolve().parents[2]
COMET_2019 = ROOT / "tests" / "data" / "real" / "dbd" / "comet-2019"
SEGMENT_154 = [COMET_2019 / f"comet-2019-222-02-154.{ext}" for ext in ("dbd", "ebd")]
SCIENCE_154 = COMET_2019 / "comet-2019-222-02-154.ebd"
METADATA = ROOT / "tests" / "netcdf" / "data" / "comet.toml"
VEHICLE = ROOT / "boards" / "vehicles" / "slocum_shallow.toml"
EPOCH = "1700000000"  # date_created of both sides


def convert(tmp_path, inputs, *args):
    cli = os.environ.get("GLIDER_CONVERT")
    if not cli:
        pytest.skip("GLIDER_CONVERT not set (run through CTest)")
    out = tmp_path / "out.nc"
    env = dict(os.environ, SOURCE_DATE_EPOCH=EPOCH)
    subprocess.run([cli, "--quiet", *map(str, inputs), "--out", str(out), *args], check=True, env=env)
    return out


def without_history(ds):
    ds = ds.copy()
    ds.attrs.pop("history")  # the command that made it: glider-convert's argv or the Python call
    return ds


def test_to_xarray_is_the_og1_file_glider_convert_writes(tmp_path, monkeypatch):
    path = convert(tmp_path, SEGMENT_154, "--format", "og1", "--metadata", str(METADATA), "--vehicle", str(VEHICLE))
    from_file = glider.read_og1(path)  # xarray's netCDF4 engine reading what the NetCDF library wrote
    monkeypatch.setenv("SOURCE_DATE_EPOCH", EPOCH)
    in_memory = glider.read_log(SEGMENT_154).to_xarray(metadata=METADATA, vehicle=VEHICLE)
    # Every variable, value, dtype, coordinate and attribute (units, _FillValue decoding, TIME as datetime64).
    xr.testing.assert_identical(without_history(in_memory), without_history(from_file))
    assert in_memory.sizes["N_MEASUREMENTS"] == 2243
    assert in_memory["TEMP"].dtype == np.float32 and in_memory["TEMP"].attrs["units"] == "degree_Celsius"
    assert in_memory["TIME"].dtype == np.dtype("datetime64[ns]")
    assert set(in_memory.coords) == {"TIME", "LATITUDE", "LONGITUDE", "DEPTH"}
    assert int(np.nanmax(in_memory["PROFILE_NUMBER"])) == 34
    assert "SPEED_THROUGH_WATER_MODEL" in in_memory and in_memory.attrs["flight_model_vehicle"] == "slocum_shallow"
    # The module-level spelling is the same call.
    again = glider.to_og1_dataset(glider.read_log(SEGMENT_154), metadata=str(METADATA), vehicle=VEHICLE)
    xr.testing.assert_identical(without_history(again), without_history(in_memory))


def test_without_metadata_only_what_the_data_say():
    log = glider.read_log(SEGMENT_154)
    full = log.to_xarray(metadata=METADATA)
    bare = log.to_xarray()
    left_out = set(full.data_vars) - set(bare.data_vars)
    assert left_out == {"TRAJECTORY", "WMO_IDENTIFIER", "PLATFORM_MODEL", "PLATFORM_SERIAL_NUMBER", "PLATFORM_NAME",
                        "PLATFORM_MAKER", "PLATFORM_DEPTH_RATING", "DEPLOYMENT_TIME", "DEPLOYMENT_LATITUDE",
                        "DEPLOYMENT_LONGITUDE", "SENSOR_CTD_0000"}
    assert "glider_no_metadata" in bare.attrs and "id" not in bare.attrs
    assert "sensor" not in bare["TEMP"].attrs and full["TEMP"].attrs["sensor"] == "SENSOR_CTD_0000"
    for name in bare.data_vars:
        xr.testing.assert_equal(bare[name], full[name])  # same data; attributes differ only by the sensor
    assert "SPEED_THROUGH_WATER_MODEL" not in bare  # no vehicle, no flight-model products


def test_bad_metadata_is_refused_naming_file_line_and_key():
    with pytest.raises(Exception, match=r"nan\.toml:\d+:\d+: platform\.depth_rating_m"):
        glider.read_log(SEGMENT_154).to_xarray(metadata=ROOT / "tests" / "netcdf" / "data" / "bad" / "nan.toml")


def test_to_pandas_has_every_column_indexed_by_time():
    log = glider.read_log(SEGMENT_154)
    frame = log.to_pandas()
    assert isinstance(frame, pd.DataFrame)
    assert list(frame.columns) == log.columns and len(frame) == len(log) == 2243
    assert frame.index.name == "time" and frame.index.dtype == np.dtype("datetime64[ns]")
    # The log's seconds as nanoseconds (a double's 0.24 us resolution in 2019).
    np.testing.assert_allclose(frame.index.values.astype(np.int64) / 1e9, log.time, rtol=0, atol=1e-6)
    assert frame.index.is_monotonic_increasing
    for name in ("m_depth", "m_pitch", "sci_water_temp"):
        np.testing.assert_array_equal(frame[name].to_numpy(), log[name])


def test_read_log_opens_the_og1_file_glider_convert_wrote(tmp_path):
    path = convert(tmp_path, SEGMENT_154, "--format", "og1", "--metadata", str(METADATA))
    back = glider.read_log(path)
    binary = glider.read_log(SEGMENT_154)
    assert len(back) == len(binary) == 2243
    np.testing.assert_array_equal(back.time, binary.time)  # TIME is a double: exact
    depth = binary["m_depth"]
    ok = ~np.isnan(depth)
    np.testing.assert_array_equal(back["m_depth"][ok], depth[ok])
    # PITCH is a float32 in degrees: within float32 precision of the binary's radians.
    pitch, pitch_back = binary["m_pitch"], back["m_pitch"]
    ok = ~np.isnan(pitch)
    assert np.isnan(pitch_back[~ok]).all()
    np.testing.assert_allclose(pitch_back[ok], pitch[ok], rtol=2e-7, atol=1e-9)
    assert "PHASE" in back and "PROFILE_NUMBER" in back  # the other variables keep their OG1 names


def test_science_files_alone_read_as_glider_convert_reads_them(tmp_path):
    log = glider.read_log(SCIENCE_154)
    assert log.columns[0] == "sci_m_present_time"
    assert len(log) == 9620
    # glider-convert's CSV of the same file reads back as the same log (7 significant digits).
    csv = tmp_path / "science.csv"
    subprocess.run([os.environ.get("GLIDER_CONVERT") or pytest.skip("GLIDER_CONVERT not set"), "--quiet",
                    str(SCIENCE_154), "--out", str(csv)], check=True)
    from_csv = glider.read_log(csv)
    assert from_csv.columns == [c for c in log.columns if c in from_csv.columns]
    assert len(from_csv) == len(log)
    for name in from_csv.columns:
        a, b = log[name], from_csv[name]
        assert np.array_equal(np.isnan(a), np.isnan(b)), name
        ok = ~np.isnan(b)
        assert np.allclose(a[ok], b[ok], rtol=1e-6, atol=1e-5), name
    # And its OG1.0 dataset is glider-convert's file of it.
    path = convert(tmp_path, [SCIENCE_154], "--format", "og1", "--metadata", str(METADATA))
    os.environ["SOURCE_DATE_EPOCH"] = EPOCH
    try:
        in_memory = log.to_xarray(metadata=METADATA)
    finally:
        del os.environ["SOURCE_DATE_EPOCH"]
    xr.testing.assert_identical(without_history(in_memory), without_history(glider.read_og1(path)))
    assert int(np.nanmax(in_memory["PROFILE_NUMBER"])) == 34


@pytest.mark.parametrize("library,package,call", [
    ("xarray", "python3-xarray", "log.to_xarray()"),
    ("pandas", "python3-pandas", "log.to_pandas()"),
    ("netCDF4", "python3-netcdf4", "glider.read_og1('x.nc')"),
])
def test_a_missing_optional_library_names_its_debian_package(library, package, call):
    # A fresh interpreter where the library cannot be imported (sys.modules entry None).
    code = (f"import sys; sys.modules[{library!r}] = None\n"
            f"import glider\nlog = glider.read_log({str(SCIENCE_154)!r})\n"
            f"try:\n    {call}\nexcept ImportError as e:\n    print(e)\nelse:\n    print('no error')\n")
    out = subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, text=True).stdout
    assert f"apt-get install {package}" in out, out
