# SPDX-License-Identifier: Apache-2.0
"""One SIL flight: per-run vehicle/environment files, the glider-sil
subprocess, and its result as a flat dictionary of metrics.

Cards, campaigns and Slurm shards all fly through fly(): the real
glider-sil binary, as a user's CI would run it. The metrics come from its
--summary-json file (docs/sil-summary.md; metrics_from_summary); their
names are the contract every other module uses (docs/campaigns.md lists them)."""

import json
import math
import os
import subprocess
import tempfile
import threading
import time
import tomllib

import tomli_w

# Parameters that are not a vehicle-file key: the environment's current as a
# depth-uniform speed and direction (towards, degrees clockwise from north),
# or a scale on the file's own current profile; `env.KEY` sets any other
# environment key, `mission.KEY` a key of a TOML mission.
CURRENT_KEYS = ("current.speed_m_s", "current.direction_deg", "current.scale")


class RunError(Exception):
    """A run that could not be set up (bad parameter, bad file)."""


def _set_dotted(table, dotted, value, what):
    parts = dotted.split(".")
    node = table
    for part in parts[:-1]:
        child = node.setdefault(part, {})
        if not isinstance(child, dict):
            raise RunError(f"{what}: '{dotted}': '{part}' is not a table")
        node = child
    node[parts[-1]] = value


def _load_toml(path):
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise RunError(f"{path}: {error}") from error


def _apply_current(env, params, env_path):
    speed = params.get("current.speed_m_s")
    direction = params.get("current.direction_deg")
    scale = params.get("current.scale")
    if speed is None and direction is None and scale is None:
        return
    profile = env.setdefault("profile", {"depth_m": [0.0]})
    depths = profile.get("depth_m", [0.0])
    if speed is not None or direction is not None:
        if speed is None or direction is None:
            raise RunError("current.speed_m_s and current.direction_deg go together")
        if not (speed >= 0.0 and math.isfinite(speed)):
            raise RunError(f"current.speed_m_s = {speed}: must be >= 0")
        east = speed * math.sin(math.radians(direction))
        north = speed * math.cos(math.radians(direction))
        profile["current_east_m_s"] = [east] * len(depths)
        profile["current_north_m_s"] = [north] * len(depths)
    if scale is not None:
        for key in ("current_east_m_s", "current_north_m_s"):
            if key in profile:
                profile[key] = [scale * v for v in profile[key]]
        if "current_east_m_s" not in profile and "current_north_m_s" not in profile:
            raise RunError(f"current.scale: {env_path or 'still water'} has no current to scale")


def write_run_files(setup, params, workdir):
    """Writes the vehicle (and environment, mission) files of one run with
    `params` applied; returns their paths (base paths when unchanged)."""
    vehicle_params, env_params, mission_params = {}, {}, {}
    for name, value in params.items():
        if name in CURRENT_KEYS:
            continue
        if name.startswith("env."):
            env_params[name[4:]] = value
        elif name.startswith("mission."):
            mission_params[name[8:]] = value
        elif name.startswith("fault."):
            continue  # fault times: handled by fault_arguments
        else:
            vehicle_params[name] = value
    paths = {"vehicle": setup["vehicle"], "environment": setup.get("environment"), "mission": setup["mission"]}
    if vehicle_params:
        vehicle = _load_toml(setup["vehicle"])
        for name, value in vehicle_params.items():
            _set_dotted(vehicle, name, value, setup["vehicle"])
        paths["vehicle"] = os.path.join(workdir, "vehicle.toml")
        with open(paths["vehicle"], "wb") as f:
            tomli_w.dump(vehicle, f)
    if env_params or any(k in params for k in CURRENT_KEYS):
        env = _load_toml(setup["environment"]) if setup.get("environment") else {}
        if not env:  # still water at the vehicle's trim density, as glider-sil's default
            trim = _load_toml(setup["vehicle"]).get("buoyancy", {}).get("trim_density_kg_m3", 1025.0)
            env = {"profile": {"depth_m": [0.0], "density_kg_m3": [trim]}}
        for name, value in env_params.items():
            _set_dotted(env, name, value, setup.get("environment") or "environment")
        _apply_current(env, params, setup.get("environment"))
        paths["environment"] = os.path.join(workdir, "environment.toml")
        with open(paths["environment"], "wb") as f:
            tomli_w.dump(env, f)
    if mission_params:
        if not setup["mission"].endswith(".toml"):
            raise RunError(f"mission.* parameters need a TOML mission, not {setup['mission']}")
        mission = _load_toml(setup["mission"])
        for name, value in mission_params.items():
            _set_dotted(mission, name, value, setup["mission"])
        paths["mission"] = os.path.join(workdir, "mission.toml")
        with open(paths["mission"], "wb") as f:
            tomli_w.dump(mission, f)
    return paths


def fault_arguments(faults, params):
    """--fault NAME@TIMEs for each fault; `fault.NAME.at_s` in params moves it."""
    args = []
    for fault in faults:
        at_s = params.get(f"fault.{fault['name']}.at_s", fault["at_s"])
        args += ["--fault", f"{fault['name']}@{at_s!r}s"]
    return args


def command(sil_binary, setup, paths, seed, params):
    cmd = [sil_binary, "--mission", paths["mission"], "--vehicle", paths["vehicle"], "--seed", str(seed)]
    if paths.get("environment"):
        cmd += ["--env", paths["environment"]]
    for key, flag in (("max_sim_time_s", "--max-sim-time-s"), ("max_working_depth_m", "--max-working-depth-m"),
                      ("legs", "--legs"), ("heading_law", "--heading-law"), ("dr", "--dr"),
                      ("heading_deg", "--heading-deg")):
        if setup.get(key) is not None:
            cmd += [flag, str(setup[key])]
    cmd += fault_arguments(setup.get("faults", []), params)
    return cmd


def metrics_from_summary(j):
    """The metrics from glider-sil's summary JSON (schema glider-sil-summary/1)."""
    if j.get("schema") != "glider-sil-summary/1":
        raise RunError(f"summary schema {j.get('schema')!r}, expected glider-sil-summary/1")
    m = {"result": j["result"], "abort.cause": "none"}
    if j["abort"]:
        a = j["abort"]
        m["abort.cause"] = a["cause"]
        m["abort.time_s"] = a["time_s"]
        m["abort.surfaced_after_s"] = math.inf if a["surfaced_after_s"] is None else a["surfaced_after_s"]
    for key in ("yos", "max_depth_m", "segments", "energy_kj", "charge_ah", "distance_km", "sim_time_s"):
        m[key] = j[key]
    m["waypoints.reached"] = j["waypoints_reached"]
    for n, w in enumerate(j["waypoints"], 1):
        m[f"waypoint.{n}.reached_s"] = w["time_s"]
        if "index" in w:
            m[f"waypoint.{n}.index"] = w["index"]
            m[f"waypoint.{n}.distance_m"] = w["true_distance_m"]
    m["surfacings"] = len(j["surfacings"])
    for n, s in enumerate(j["surfacings"], 1):
        m[f"surfacing.{n}.time_s"] = s["time_s"]
        m[f"surfacing.{n}.dr_error_m"] = s["dr_error_m"]
    if j["dr_error_m_per_km"] is not None:
        m["dr_error_m_per_km"] = j["dr_error_m_per_km"]
        m["dr_error_m"] = j["dr_error_max_m"]
    for kind in ("dives", "climbs"):
        g = j[kind]
        m[f"{kind}.pitch_deg"] = g["mean_pitch_deg"]
        m[f"{kind}.depth_rate_m_s"] = g["mean_depth_rate_m_s"]
        m[f"{kind}.samples"] = g["settled_samples"]
    m["pitch_error_deg"] = max(j["dives"]["max_pitch_error_deg"], j["climbs"]["max_pitch_error_deg"])
    m["pitch_error_rms_deg"] = max(j["dives"]["rms_pitch_error_deg"], j["climbs"]["rms_pitch_error_deg"])
    return m


def run_measured(cmd, workdir, timeout_s):
    """Runs cmd with its output in files; returns (exit status or None on
    timeout, stdout, stderr, CPU seconds of the process: wait4's rusage, the
    cost of the run itself however loaded the machine is)."""
    out_path, err_path = os.path.join(workdir, "stdout"), os.path.join(workdir, "stderr")
    with open(out_path, "w") as out, open(err_path, "w") as err:
        proc = subprocess.Popen(cmd, stdout=out, stderr=err, stdin=subprocess.DEVNULL)
        timed_out = threading.Event()
        timer = threading.Timer(timeout_s, lambda: (timed_out.set(), proc.kill()))
        timer.start()
        try:
            _, status, usage = os.wait4(proc.pid, 0)
        finally:
            timer.cancel()
    proc.returncode = os.waitstatus_to_exitcode(status)  # reaped here: Popen must not wait again
    with open(out_path) as f_out, open(err_path) as f_err:
        code = None if timed_out.is_set() else proc.returncode
        return code, f_out.read(), f_err.read(), usage.ru_utime + usage.ru_stime


def fly(sil_binary, setup, params, seed, timeout_s=3600.0):
    """Flies one run; returns (metrics, cost {wall_s, cpu_s}, error text or "")."""
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="glider-run-") as workdir:
        try:
            paths = write_run_files(setup, params, workdir)
        except RunError as error:
            return {"result": "error"}, {"wall_s": 0.0, "cpu_s": 0.0}, str(error)
        cmd = command(sil_binary, setup, paths, seed, params)
        summary_path = os.path.join(workdir, "summary.json")
        cmd += ["--quiet", "--summary-json", summary_path]
        status, stdout, stderr, cpu_s = run_measured(cmd, workdir, timeout_s)
        cost = {"wall_s": time.monotonic() - start, "cpu_s": cpu_s}
        if status is None:
            return {"result": "error"}, cost, f"glider-sil ran longer than {timeout_s} s"
        try:
            if os.path.exists(summary_path):  # written for every run that flew
                with open(summary_path) as f:
                    return metrics_from_summary(json.load(f)), cost, ""
        except (RunError, KeyError, TypeError, ValueError) as error:
            return {"result": "error"}, cost, f"cannot read glider-sil's summary: {error}"
        why = stderr.strip().replace(workdir + "/", "") or f"exit status {status}"
        return {"result": "error"}, cost, why
