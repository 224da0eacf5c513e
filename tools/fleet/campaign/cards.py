# SPDX-License-Identifier: Apache-2.0
"""Flight test cards: a TOML file naming a mission, vehicle, environment,
faults, seed and expectations (docs/campaigns.md). load_card() reads and
checks one; check() compares a run's metrics with its expectations."""

import json
import math
import os
import re
import tomllib

# Metric names a card may expect (sil_run.parse_summary_text makes them).
METRICS = {"result", "abort.cause", "abort.time_s", "abort.surfaced_after_s", "yos", "max_depth_m",
           "pitch_error_deg", "pitch_error_rms_deg", "dives.pitch_deg", "climbs.pitch_deg", "dives.depth_rate_m_s",
           "climbs.depth_rate_m_s", "dives.samples", "climbs.samples", "segments", "waypoints.reached", "surfacings", "dr_error_m_per_km",
           "dr_error_m", "distance_km", "energy_kj", "charge_ah", "sim_time_s"}
INDEXED_METRICS = re.compile(r"^(waypoint\.\d+\.(reached_s|distance_m|index)|surfacing\.\d+\.(time_s|dr_error_m))$")
RESULTS = ("complete", "aborted", "stopped")  # stopped: by the run's time limit
# The phrasing of some bounds, as (metric, bound).
SUGAR = {"abort.surfaced_within_s": ("abort.surfaced_after_s", "max"), "depth.max_m": ("max_depth_m", "max"),
         "energy.max_kj": ("energy_kj", "max")}
WAYPOINT_BEFORE = re.compile(r"^waypoint\.(\d+)\.reached_before_s$")

# Keys a card (and a campaign) may have at the top level.
SETUP_KEYS = {"name", "description", "mission", "vehicle", "environment", "seed", "max_sim_time_s",
              "max_working_depth_m", "legs", "heading_law", "dr", "heading_deg", "fault", "set", "expect"}


# The numbers of a card and their ranges: (min, max, unit, integer). The same
# as glider-sil's options they become (--max-sim-time-s ...); tests/cli checks
# this table against glider-sil --list-numeric-options, so they cannot drift.
# at_s is a [[fault]]'s time (glider-sil --fault NAME@TIME: at most 60 days).
NUMBER_KEYS = {
    "seed": (0, 2**63 - 1, "", True),
    "max_sim_time_s": (0.0, 60.0 * 86400.0, "s", False),
    "max_working_depth_m": (1.0, 11000.0, "m", False),
    "heading_deg": (-360.0, 360.0, "deg", False),
    "legs": (-2, 100000, "", True),
}
FAULT_TIME_RANGE = (0.0, 60.0 * 86400.0, "s", False)


class CardError(Exception):
    pass


def check_number(key, value, where):
    """The value of `key` if it is a number (a whole one where the key needs
    it) inside its range; else CardError naming the key, value and range."""
    low, high, unit, integer = FAULT_TIME_RANGE if key == "at_s" else NUMBER_KEYS[key]
    allowed = f"[{low:g}, {high:g}]{' ' + unit if unit else ''}" if not integer else f"[{low}, {high}]"
    kind = "a whole number" if integer else "a number"
    is_number = isinstance(value, int) or (isinstance(value, float) and not integer)
    if isinstance(value, bool) or not is_number or not (low <= value <= high):  # NaN fails the comparison
        raise CardError(f"{where}: {key} = {value!r}: must be {kind} in the allowed range {allowed}")
    return value


def _flatten(table, prefix=""):
    for key, value in table.items():
        path = f"{prefix}{key}"
        if isinstance(value, dict):
            yield from _flatten(value, path + ".")
        else:
            yield path, value


def _known_metric(name):
    return name in METRICS or INDEXED_METRICS.match(name) is not None


def parse_expectations(expect, where):
    """[expect] as a list of (text, metric, bound, value); bound is min, max or equals."""
    if not isinstance(expect, dict):
        raise CardError(f"{where}: expect = {expect!r}: must be an [expect] table of metric = value")
    out = []
    for path, value in _flatten(expect):
        text = f"{path} = {json.dumps(value)}" if isinstance(value, str) else f"{path} = {value}"  # as in TOML
        if path in SUGAR:
            metric, bound = SUGAR[path]
        elif WAYPOINT_BEFORE.match(path):
            metric, bound = f"waypoint.{WAYPOINT_BEFORE.match(path).group(1)}.reached_s", "max"
        elif path.endswith(".min") or path.endswith(".max"):
            metric, bound = path[:-4], path[-3:]
        else:
            metric, bound = path, "equals"
        if not _known_metric(metric):
            raise CardError(f"{where}: [expect] {path}: unknown metric '{metric}' "
                            f"(known: {', '.join(sorted(METRICS))}, waypoint.N.*, surfacing.N.*)")
        if bound != "equals" and not (isinstance(value, (int, float)) and not isinstance(value, bool)
                                      and math.isfinite(value)):
            raise CardError(f"{where}: [expect] {path} = {value!r}: a bound must be a finite number")
        if metric == "result" and value not in RESULTS:
            raise CardError(f"{where}: [expect] result = {value!r}: allowed {', '.join(RESULTS)}")
        out.append((text, metric, bound, value))
    return out


def _path(base_dir, value, key, where):
    if not isinstance(value, str):
        raise CardError(f"{where}: {key} = {value!r}: must be a file path (string)")
    path = value if os.path.isabs(value) else os.path.normpath(os.path.join(base_dir, value))
    if not os.path.isfile(path):
        raise CardError(f"{where}: {key} = {value!r}: no such file ({path})")
    return path


def load_setup(doc, path, allowed_extra=()):
    """The flight a card or campaign describes: paths resolved relative to
    the file, faults, fixed parameter settings."""
    unknown = set(doc) - SETUP_KEYS - set(allowed_extra)
    if unknown:
        raise CardError(f"{path}: unknown key(s) {', '.join(sorted(unknown))} (allowed: "
                        f"{', '.join(sorted(SETUP_KEYS | set(allowed_extra)))})")
    base = os.path.dirname(os.path.abspath(path))
    for key in ("mission", "vehicle"):
        if key not in doc:
            raise CardError(f"{path}: '{key}' is required")
    setup = {"name": doc.get("name", os.path.splitext(os.path.basename(path))[0]),
             "description": doc.get("description", ""),
             "mission": _path(base, doc["mission"], "mission", path),
             "vehicle": _path(base, doc["vehicle"], "vehicle", path),
             "environment": _path(base, doc["environment"], "environment", path) if "environment" in doc else None,
             "seed": 1}
    for key in NUMBER_KEYS:
        if key in doc:
            setup[key] = check_number(key, doc[key], path)
    for key, allowed in (("heading_law", ("proportional", "slocum", "compensated")), ("dr", ("assumed", "model"))):
        if key in doc:
            if doc[key] not in allowed:
                raise CardError(f"{path}: {key} = {doc[key]!r}: allowed {', '.join(allowed)}")
            setup[key] = doc[key]
    for key in ("name", "description"):
        if not isinstance(setup[key], str):
            raise CardError(f"{path}: {key} = {setup[key]!r}: must be a string")
    faults = doc.get("fault", [])
    if not isinstance(faults, list):
        raise CardError(f"{path}: fault = {faults!r}: must be [[fault]] tables (name, at_s)")
    setup["faults"] = []
    for i, fault in enumerate(faults):
        if not isinstance(fault, dict) or set(fault) != {"name", "at_s"} or not isinstance(fault["name"], str):
            raise CardError(f"{path}: [[fault]] #{i + 1} = {fault!r}: needs name = \"...\" and at_s (s)")
        check_number("at_s", fault["at_s"], f"{path}: [[fault]] #{i + 1}")
        setup["faults"].append({"name": fault["name"], "at_s": float(fault["at_s"])})
    # [set] keys are parameter names, quoted ("buoyancy.offset_kg") or nested: both give the dotted name.
    if not isinstance(doc.get("set", {}), dict):
        raise CardError(f"{path}: set = {doc['set']!r}: must be a [set] table of parameter = value")
    setup["set"] = dict(_flatten(doc.get("set", {})))
    return setup


def read_toml(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except OSError as error:
        raise CardError(f"{path}: {error.strerror}") from error
    except tomllib.TOMLDecodeError as error:
        raise CardError(f"{path}: {error}") from error


def load_card(path):
    doc = read_toml(path)
    setup = load_setup(doc, path)
    if "expect" not in doc or not doc["expect"]:
        raise CardError(f"{path}: a card needs an [expect] table (what to check)")
    setup["expect"] = parse_expectations(doc["expect"], path)
    setup["path"] = path
    return setup


def _format(value):
    if isinstance(value, float):
        return "inf" if math.isinf(value) else f"{value:.6g}"
    return str(value)


def check(expectations, metrics, error=""):
    """[(expectation text, measured text, passed)] for one run."""
    rows = []
    for text, metric, bound, value in expectations:
        if error:
            rows.append((text, f"run failed: {error}", False))
            continue
        if metric not in metrics:
            absent = "not reached" if metric.startswith("waypoint.") else "absent"
            rows.append((text, f"{metric}: {absent}", False))
            continue
        measured = metrics[metric]
        if bound == "equals":
            passed = measured == value
        elif bound == "max":
            passed = measured <= value  # NaN fails
        else:
            passed = measured >= value
        rows.append((text, f"{metric} = {_format(measured)}", passed))
    return rows
