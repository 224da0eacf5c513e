// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/speed_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace glider::diagnose {

double implied_water_velocity(double measured_rate_m_s, double model_rate_through_water_m_s, double reference_speed_m_s,
                              double model_speed_m_s) {
  if (!std::isfinite(measured_rate_m_s) || !std::isfinite(model_rate_through_water_m_s) ||
      !std::isfinite(reference_speed_m_s) || !std::isfinite(model_speed_m_s) || std::abs(model_speed_m_s) < 1e-3) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return measured_rate_m_s - reference_speed_m_s * model_rate_through_water_m_s / model_speed_m_s;
}

double check_reference_by_yo(std::vector<SpeedOfYo>& by_yo, std::span<const double> implied, std::span<const int> yo,
                             double bound_m_s) {
  std::map<int, std::pair<double, std::size_t>> sums;  // per yo: sum, count of finite values
  for (std::size_t k = 0; k < implied.size(); ++k) {
    if (!std::isfinite(implied[k])) continue;
    auto& [sum, n] = sums[yo[k]];
    sum += implied[k];
    ++n;
  }
  std::vector<double> means;
  for (SpeedOfYo& y : by_yo) {
    const auto it = sums.find(y.yo);
    if (it == sums.end() || it->second.second == 0) continue;
    y.implied_water_w_m_s = it->second.first / static_cast<double>(it->second.second);
    means.push_back(y.implied_water_w_m_s);
  }
  if (means.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(means.begin(), means.end());
  const std::size_t h = means.size() / 2;
  const double median = means.size() % 2 ? means[h] : 0.5 * (means[h - 1] + means[h]);
  for (SpeedOfYo& y : by_yo) {
    if (std::isfinite(y.implied_water_w_m_s))
      y.reference_consistent = std::abs(y.implied_water_w_m_s - median) <= bound_m_s;
  }
  return median;
}

}  // namespace glider::diagnose
