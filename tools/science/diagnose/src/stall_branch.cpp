// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/stall_branch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "glider/model/steady_glide.hpp"

namespace glider::diagnose {

double stall_onset_lift(const model::VehicleParams& nominal, const EffectValues& values, double pitch_rad) {
  const EffectInfo& lift = info(Effect::kLiftChange);
  auto stalls = [&](double factor) {
    EffectValues x = values;
    x[static_cast<std::size_t>(Effect::kLiftChange)] = factor;
    return model::has_stall_glide(apply(nominal, x, nominal.hull_reference_temperature_c).hydro, pitch_rad);
  };
  // Down from the most lift: the first lift with a stall state besides the
  // flight (with far less lift the flight branch goes too and the stall is
  // the only glide), then bisected between it and the step above.
  constexpr double kScanStep = 0.02;
  double high = lift.plausible_max;
  if (stalls(high)) return high;
  double low = high - kScanStep;
  while (low > lift.plausible_min && !stalls(low)) {
    high = low;
    low -= kScanStep;
  }
  if (low <= lift.plausible_min) return 0.0;
  while (high - low > 1e-4) {
    const double mid = 0.5 * (low + high);
    (stalls(mid) ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

LiftBand stall_onset_band(const model::VehicleParams& nominal, const EffectValues& values,
                          std::span<const double> pitch_rad) {
  LiftBand band{std::numeric_limits<double>::infinity(), 0.0};
  for (const double sign : {-1.0, 1.0}) {
    std::vector<double> pitch;
    for (double p : pitch_rad) {
      if (std::isfinite(p) && p * sign > 0.0) pitch.push_back(std::abs(p));
    }
    if (pitch.size() < 20) continue;
    std::sort(pitch.begin(), pitch.end());
    for (const double q : {0.01, 0.99}) {
      const double onset =
          stall_onset_lift(nominal, values, sign * pitch[static_cast<std::size_t>(q * (pitch.size() - 1))]);
      if (onset <= 0.0) continue;  // never stalls at this pitch: no tooth
      band.low = std::min(band.low, onset);
      band.high = std::max(band.high, onset);
    }
  }
  if (band.high <= 0.0) return {};
  return band;
}

}  // namespace glider::diagnose
