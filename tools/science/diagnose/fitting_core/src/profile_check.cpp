// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/profile_check.hpp"

#include <algorithm>
#include <cmath>

#include "glider/fitting_core/delay_search.hpp"

namespace glider::fitting_core {

double profile_checked_half_width(double value, double half, double fitted_rss, double n_eff, int k, double min_step,
                                  const std::function<double(double)>& rss_at) {
  const double limit = profile_threshold(fitted_rss, n_eff, k);
  const double rise = limit - fitted_rss;
  if (!std::isfinite(value) || !std::isfinite(fitted_rss) || !(rise > 0.0)) return half;
  const bool half_usable = std::isfinite(half) && half > 0.0;
  double out = half_usable ? half : 0.0;
  for (double side : {-1.0, 1.0}) {
    if (half_usable && rss_at(value + side * half) - fitted_rss >= kProfileRiseKept * rise) continue;
    // The Jacobian's end sits where the residual has hardly moved: step out.
    double step = std::max(half_usable ? half : 0.0, min_step);
    double reached = step;
    for (int i = 0; i < kProfileMaxDoublings; ++i, step *= 2.0) {
      reached = step;  // the farthest tried: a lower bound where none crosses
      const double rss = rss_at(value + side * step);
      if (!std::isfinite(rss) || rss >= limit) break;  // a flight that fails is outside too
    }
    out = std::max(out, reached);
  }
  return out;
}

}  // namespace glider::fitting_core
