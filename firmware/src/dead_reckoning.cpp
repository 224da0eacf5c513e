// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/dead_reckoning.hpp"

#include <algorithm>
#include <cmath>

namespace glider::fw {

double DeadReckoning::alpha_for(double pitch_rad) const {
  if (config_.method == DrMethod::kAssumedAlpha) return config_.assumed_alpha_rad;
  const auto& table = pitch_rad < 0.0 ? config_.dive_alpha_rad : config_.climb_alpha_rad;
  const double position = (std::fabs(pitch_rad) - config_.table_first_pitch_rad) / config_.table_step_rad;
  const double clamped = std::clamp(position, 0.0, static_cast<double>(table.size() - 1));
  const auto i = static_cast<std::size_t>(clamped);
  if (i + 1 >= table.size()) return table.back();
  const double f = clamped - static_cast<double>(i);
  return table[i] + f * (table[i + 1] - table[i]);
}

double DeadReckoning::horizontal_speed(double pitch_rad, double depth_rate_m_s) const {
  if (std::fabs(pitch_rad) < config_.min_pitch_rad) return 0.0;
  // A glider moves along its glide path: diving nose down, climbing nose up.
  const bool consistent = (pitch_rad < 0.0 && depth_rate_m_s > 0.0) || (pitch_rad > 0.0 && depth_rate_m_s < 0.0);
  if (!consistent) return 0.0;
  // The glide path is steeper than the pitch by the angle of attack
  // (xi = theta - alpha, alpha of the pitch's sign on the flight branch).
  const double glide_path = std::fabs(pitch_rad) + alpha_for(pitch_rad);
  return std::min(std::fabs(depth_rate_m_s) / std::tan(glide_path), config_.max_speed_m_s);
}

void DeadReckoning::update(double pitch_rad, double heading_rad, double depth_rate_m_s, EastNorth current_m_s,
                           double dt_s) {
  const double inferred = horizontal_speed(pitch_rad, depth_rate_m_s);
  if (config_.method == DrMethod::kFlightModel && inferred == 0.0 && std::fabs(pitch_rad) < config_.min_pitch_rad) {
    // Through an inflection the glider coasts: the flight model's speed
    // decays with its drag time constant instead of dropping to zero.
    speed_ *= std::exp(-dt_s / config_.coast_time_constant_s);
  } else {
    speed_ = inferred;
  }
  position_.east_m += (speed_ * std::sin(heading_rad) + current_m_s.east_m) * dt_s;
  position_.north_m += (speed_ * std::cos(heading_rad) + current_m_s.north_m) * dt_s;
  distance_m_ += speed_ * dt_s;
}

}  // namespace glider::fw
