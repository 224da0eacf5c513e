// SPDX-License-Identifier: Apache-2.0
#pragma once
// A water column from CTD samples (a glider's own casts, or a ship's): the
// in-situ density of every sample by TEOS-10 (seawater.hpp), averaged in
// depth bins into the profile nodes of a WaterColumn. Init-time code.
#include <vector>

#include "glider/model/environment.hpp"

namespace glider::model {

struct CtdSample {
  double depth_m = 0.0;
  double temperature_c = 0.0;
  double conductivity_s_m = 0.0;
  double pressure_dbar = 0.0;
};

// Samples with an invalid TEOS-10 result are skipped; empty bins are left
// out. Throws std::invalid_argument if no bin has a valid sample.
WaterColumn water_column_from_ctd(const std::vector<CtdSample>& samples, double bin_m = 1.0);

}  // namespace glider::model
