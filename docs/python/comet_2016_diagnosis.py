#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# %% [markdown]
# # comet 2016: from the glider's own files to a diagnosis, in Python
#
# Notebook-style (cells marked `# %%`; runs as a script too):
#
#     ./glider build && PYTHONPATH=build/release/tools/files/python python3 docs/python/comet_2016_diagnosis.py [OUT_DIR]
#
# Reads the 20 binary files of comet's 2016 Baltic deployment (10 .dbd + 10
# .ebd, sensor lists in cac/) as one log, flies the nominal vehicle through
# it (time-domain model), diagnoses what the model gets wrong and plots it.

# %%
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files, no display needed
import matplotlib.pyplot as plt
import numpy as np

import glider

ROOT = Path(__file__).resolve().parents[2]
FILES = ROOT / "tests" / "data" / "real" / "dbd" / "comet-2016"
OUT = Path(sys.argv[1]) if len(sys.argv) > 1 else Path("build/python-example")
OUT.mkdir(parents=True, exist_ok=True)

# %% [markdown]
# ## The log: every sensor of the flight and science files, on the flight computer's time

# %%
log = glider.read_log(FILES)  # a directory: files in segment order, caches from FILES/cac
print(f"{log.source}: {len(log)} rows, {len(log.columns)} columns")
t_h = (log.time - log.time[0]) / 3600.0
depth, temperature = log["m_depth"], log["sci_water_temp"]
print(f"depth {np.nanmin(depth):.1f}..{np.nanmax(depth):.1f} m, "
      f"temperature {np.nanmin(temperature):.1f}..{np.nanmax(temperature):.1f} degC")

# %% [markdown]
# ## The nominal vehicle flown through the log (time-domain model)

# %%
vehicle = glider.load_vehicle(ROOT / "boards" / "vehicles" / "slocum_comet.toml")
flown = glider.model_depth_rate(log, vehicle, model="dynamic")
rms = np.sqrt(np.nanmean((flown["model_m_s"] - flown["measured_m_s"]) ** 2))
print(f"vehicle {vehicle.name}: depth-rate RMS of the nominal model {rms * 100:.2f} cm/s "
      f"over {np.count_nonzero(~np.isnan(flown['model_m_s']))} samples")

# %% [markdown]
# ## The diagnosis: the same object as `glider-diagnose --json`

# %%
d = glider.diagnose(log, vehicle)
print(f"cause: {d['cause']}; baseline RMS {d['baseline']['rms_depth_rate_m_s'] * 100:.2f} cm/s, "
      f"extended {d['extended']['rms_depth_rate_m_s'] * 100:.2f} cm/s, held-out gain {d['gain'] * 100:.0f} %")
for f in d["findings"]:
    print(f"  {f['effect']}: {f['value']:.4g} {f['unit']} (95 % {f['ci95'][0]:.3g}..{f['ci95'][1]:.3g})"
          f"{'' if f['fitted'] else ' (not kept)'}")

# %% [markdown]
# ## Plots

# %%
fig, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
axes[0].plot(t_h, depth, lw=0.8)
axes[0].invert_yaxis()
axes[0].set_ylabel("depth (m)")
axes[0].set_title(f"comet 2016 from its binary files: cause '{d['cause']}'")
ft_h = (flown["time_s"] - log.time[0]) / 3600.0
axes[1].plot(ft_h, flown["measured_m_s"], ".", ms=1.5, label="measured")
axes[1].plot(ft_h, flown["model_m_s"], ".", ms=1.5, label=f"nominal {vehicle.name}")
axes[1].set_ylabel("depth rate (m/s, + down)")
axes[1].legend(loc="upper right", markerscale=6)
axes[2].plot(ft_h, flown["model_m_s"] - flown["measured_m_s"], ".", ms=1.5)
axes[2].axhline(0.0, color="k", lw=0.5)
axes[2].set_ylabel("model - measured (m/s)")
axes[2].set_xlabel("hours since the first row")
fig.tight_layout()
fig.savefig(OUT / "comet_2016_diagnosis.png", dpi=110)

fig, ax = plt.subplots(figsize=(6, 6))
by_depth = d["baseline"]["by_depth"]
ax.barh([(b["from_m"] + b["to_m"]) / 2 for b in by_depth],
        [np.nan if b["rms_depth_rate_m_s"] is None else b["rms_depth_rate_m_s"] * 100 for b in by_depth],
        height=[0.9 * (b["to_m"] - b["from_m"]) for b in by_depth])
ax.invert_yaxis()
ax.set_xlabel("nominal model depth-rate RMS (cm/s)")
ax.set_ylabel("depth (m)")
fig.tight_layout()
fig.savefig(OUT / "comet_2016_rms_by_depth.png", dpi=110)
print(f"plots in {OUT}/")
