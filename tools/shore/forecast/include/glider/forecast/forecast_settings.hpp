// SPDX-License-Identifier: Apache-2.0
#pragma once
// The pilot's per-glider forecast settings: GLIDER/forecast.toml (the shore's
// glider folder), overridden by the command line (docs/forecast.md,
// "The pilot's prior"):
//   [current_prior]
//   mode = "evidence"          # evidence | fixed | off
//   mean_sigma_m_s = 0.10      # 0-2
//   m2_sigma_m_s = 0.25        # 0-2
//   estimate_sigma_m_s = 0.02  # 0.001-1
//   position_sigma_m = 100     # 0-5000 (0: an estimate's error does not grow as its segment shortens)
// A bad value (NaN, out of range, an unknown key, a wrong type) is an error
// naming file:line, the key, the value and the allowed range.
#include <filesystem>
#include <optional>

#include "glider/forecast/tidal_prior.hpp"

namespace glider::forecast {

// What the command line gave (unset: the file's, else the default).
struct PriorOverrides {
  std::optional<PriorMode> mode;
  std::optional<double> mean_sigma_m_s, m2_sigma_m_s, estimate_sigma_m_s, position_sigma_m;
};

// The prior for this glider: defaults, then GLIDER/forecast.toml, then
// `overrides`. Throws std::runtime_error with the message above.
TidalPrior current_prior(const std::filesystem::path& glider_dir, const PriorOverrides& overrides);

}  // namespace glider::forecast
