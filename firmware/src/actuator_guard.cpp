// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/actuator_guard.hpp"

#include <cmath>

namespace glider::fw {

double ActuatorGuard::limit(double command, double lo, double hi, double safe, std::uint64_t& clamped) {
  if (!std::isfinite(command)) {
    ++counts_.non_finite;
    return safe;
  }
  if (command < lo) {
    ++clamped;
    return lo;
  }
  if (command > hi) {
    ++clamped;
    return hi;
  }
  return command;
}

double ActuatorGuard::ballast_cc(double command) {
  // Safe = as buoyant as the pump goes: the glider rises.
  return limit(command, range_.ballast_min_cc, range_.ballast_max_cc, range_.ballast_max_cc, counts_.ballast_clamped);
}

double ActuatorGuard::battery_in(double command) {
  const double centre = 0.5 * (range_.battery_min_in + range_.battery_max_in);
  return limit(command, range_.battery_min_in, range_.battery_max_in, centre, counts_.battery_clamped);
}

double ActuatorGuard::fin_rad(double command) {
  return limit(command, -range_.fin_max_rad, range_.fin_max_rad, 0.0, counts_.fin_clamped);
}

}  // namespace glider::fw
