// SPDX-License-Identifier: Apache-2.0
#pragma once
// The last check before a command reaches an actuator: inside the vehicle's
// range, or clamped to it and counted; never NaN or infinite (a non-finite
// command becomes the safe value: pump full buoyant, slide and fin centred).
// The loaders already refuse files outside the physical ranges
// (glider/config/value_limits.hpp); this guards what the control laws make
// of them at run time. Plain numbers: no heap, no exceptions, constant time.
#include <cstdint>

namespace glider::fw {

struct ActuatorRange {
  double ballast_min_cc;
  double ballast_max_cc;
  double battery_min_in;
  double battery_max_in;
  double fin_max_rad;  // symmetric: [-fin_max_rad, fin_max_rad]
};

struct GuardCounts {
  std::uint64_t ballast_clamped = 0;
  std::uint64_t battery_clamped = 0;
  std::uint64_t fin_clamped = 0;
  std::uint64_t non_finite = 0;  // of all three, replaced by the safe value
  std::uint64_t total() const { return ballast_clamped + battery_clamped + fin_clamped + non_finite; }
};

class ActuatorGuard {
 public:
  explicit ActuatorGuard(const ActuatorRange& range) : range_(range) {}

  double ballast_cc(double command);
  double battery_in(double command);
  double fin_rad(double command);
  const GuardCounts& counts() const { return counts_; }

 private:
  double limit(double command, double lo, double hi, double safe, std::uint64_t& clamped);

  ActuatorRange range_;
  GuardCounts counts_;
};

}  // namespace glider::fw
