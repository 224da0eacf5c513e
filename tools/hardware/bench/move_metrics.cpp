// SPDX-License-Identifier: Apache-2.0
#include "move_metrics.hpp"

#include <cmath>

namespace glider::bench {

MoveMetrics measure_move(const std::vector<Sample>& samples, double start, double target) {
  MoveMetrics m;
  if (samples.empty()) return m;
  const double step = target - start;
  m.travel_time_s = samples.back().time_s;
  if (step == 0.0) return m;
  // Progress along the step, 0 at the start, 1 at the target.
  const auto progress = [&](const Sample& s) { return (s.position - start) / step; };
  double t10 = -1.0;
  double t90 = -1.0;
  double peak = 0.0;
  for (const Sample& s : samples) {
    const double p = progress(s);
    if (t10 < 0.0 && p >= 0.1) t10 = s.time_s;
    if (t90 < 0.0 && p >= 0.9) t90 = s.time_s;
    peak = std::max(peak, p);
    if (std::abs(1.0 - p) > 0.02) m.settle_time_s = s.time_s;
  }
  m.overshoot_pct = std::max(0.0, peak - 1.0) * 100.0;
  if (t10 >= 0.0 && t90 > t10) {
    m.rise_time_s = t90 - t10;
    m.mean_rate = 0.8 * std::abs(step) / m.rise_time_s;
  }
  return m;
}

}  // namespace glider::bench
