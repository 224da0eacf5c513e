// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/depth_lag.hpp"

#include <cmath>
#include <cstddef>

namespace glider::diagnose {

const char* to_string(DepthLagForm form) { return form == DepthLagForm::kFirstOrder ? "first_order" : "delay"; }

void read_depth_late(DepthLagForm form, std::span<const double> time_s, std::span<double> depth_m, double lag_s) {
  if (form == DepthLagForm::kFirstOrder) {
    first_order_lag(time_s, depth_m, lag_s);
  } else {
    delay_depth(time_s, depth_m, lag_s);
  }
}

void delay_depth(std::span<const double> time_s, std::span<double> depth_m, double lag_s) {
  const std::size_t n = depth_m.size();
  if (lag_s <= 0.0 || n < 2) return;
  // From the last sample back: the depth at k - lag only reads samples up to
  // k, which are still the undelayed ones - but the extrapolation before the
  // first sample reads the second, kept here. Times only as differences: an
  // epoch time (1.5e9 s) resolves 2e-7 s, coarser than the optimiser's step.
  const double first = depth_m[0], second = depth_m[1];
  std::size_t j = n - 1;  // the sample at or before time_s[k] - lag_s, moving down with k
  for (std::size_t k = n; k-- > 0;) {
    while (j > 0 && time_s[k] - time_s[j] < lag_s) --j;
    const double before_j = time_s[k] - time_s[j] - lag_s;  // how far time_s[k] - lag_s is after time_s[j]
    const std::size_t a = before_j < 0.0 ? 0 : j;           // j == 0 and still after: extrapolate
    const std::size_t b = a + 1 < n ? a + 1 : a;
    const double za = a == 0 ? first : depth_m[a];
    const double zb = b == 1 ? second : depth_m[b];
    const double span = time_s[b] - time_s[a];
    depth_m[k] = za + (span > 0.0 ? before_j / span : 0.0) * (zb - za);
  }
}

void first_order_lag(std::span<const double> time_s, std::span<double> depth_m, double lag_s) {
  const std::size_t n = depth_m.size();
  if (lag_s <= 0.0 || n < 2) return;
  // The reading y obeys y' = (z - y) / lag with z straight between the
  // samples: over a step dt of slope s, exactly
  //   y1 = z1 - lag s + (y0 - z0 + lag s) exp(-dt / lag).
  // The decay is taken again only where dt changes (a log's cycle is mostly
  // regular). Times only as differences (see delay_depth).
  double z0 = depth_m[0];
  const double dt0 = time_s[1] - time_s[0];
  double y = z0 - (dt0 > 0.0 ? lag_s * (depth_m[1] - z0) / dt0 : 0.0);
  double last_dt = -1.0, decay = 0.0;
  depth_m[0] = y;
  for (std::size_t k = 1; k < n; ++k) {
    const double z1 = depth_m[k];
    const double dt = time_s[k] - time_s[k - 1];
    if (dt > 0.0) {
      if (dt != last_dt) last_dt = dt, decay = std::exp(-dt / lag_s);
      const double behind = lag_s * (z1 - z0) / dt;
      y = z1 - behind + (y - z0 + behind) * decay;
    }
    depth_m[k] = y;
    z0 = z1;
  }
}

}  // namespace glider::diagnose
