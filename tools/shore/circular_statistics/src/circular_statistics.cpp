// SPDX-License-Identifier: Apache-2.0
#include "glider/circular_statistics/circular_statistics.hpp"

#include <algorithm>
#include <cmath>

namespace glider::circular_statistics {

void MeanResultant::add(double angle_rad, double weight) {
  sin_sum_ += weight * std::sin(angle_rad);
  cos_sum_ += weight * std::cos(angle_rad);
  total_weight_ += weight;
}

double MeanResultant::length() const {
  if (!(total_weight_ > 0.0)) return std::nan("");
  return std::hypot(sin_sum_, cos_sum_) / total_weight_;
}

double circular_sd_rad(double mean_resultant_length) {
  if (std::isnan(mean_resultant_length)) return mean_resultant_length;
  return std::sqrt(-2.0 * std::log(std::clamp(mean_resultant_length, 1e-300, 1.0)));
}

}  // namespace glider::circular_statistics
