// SPDX-License-Identifier: Apache-2.0
#include "glider/model/servo.hpp"

#include <algorithm>
#include <cmath>

namespace glider::model {

RateLimitedServo::RateLimitedServo(double min, double max, double rate, double initial)
    : min_(min), max_(max), rate_(rate), position_(std::clamp(initial, min, max)), target_(position_) {}

void RateLimitedServo::set_target(double target) { target_ = std::clamp(target, min_, max_); }

double RateLimitedServo::position_after(double t) const {
  const double gap = target_ - position_;
  const double reach = rate_ * t;
  if (std::abs(gap) <= reach) return target_;
  return position_ + std::copysign(reach, gap);
}

double RateLimitedServo::time_to_target() const {
  const double gap = std::abs(target_ - position_);
  return gap > 0.0 && rate_ > 0.0 ? gap / rate_ : 0.0;
}

double RateLimitedServo::velocity_after(double t) const {
  const double gap = target_ - position_;
  if (gap == 0.0 || std::abs(gap) <= rate_ * t) return 0.0;
  return std::copysign(rate_, gap);
}

}  // namespace glider::model
