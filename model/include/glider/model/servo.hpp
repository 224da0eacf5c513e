// SPDX-License-Identifier: Apache-2.0
#pragma once

namespace glider::model {

// A rate-limited position servo (battery slide, buoyancy pump): it moves at
// its full rate toward the target, stops there, and never leaves its travel.
// Over one integration step its path is known in closed form, so the
// integrator can ask where it is at any stage time.
class RateLimitedServo {
 public:
  RateLimitedServo(double min, double max, double rate, double initial);

  void set_target(double target);  // clamped to the travel
  double target() const { return target_; }
  double position() const { return position_; }

  // Position and speed `t` seconds into a step that starts now.
  double position_after(double t) const;
  double velocity_after(double t) const;

  // Seconds until it reaches the target and stops (0 if it is there).
  double time_to_target() const;

  void advance(double dt) { position_ = position_after(dt); }

 private:
  double min_, max_, rate_;
  double position_;
  double target_;
};

}  // namespace glider::model
