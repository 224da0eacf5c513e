// SPDX-License-Identifier: Apache-2.0
#pragma once

namespace glider::fw {

struct PiGains {
  double kp = 0.0;       // output units per error unit
  double ki = 0.0;       // output units per (error unit * s)
  double out_min = 0.0;  // actuator limits
  double out_max = 0.0;
};

// PI controller with output saturation and conditional integration:
// while the output is saturated the integrator may only move the output back
// inside the limits, never push it further out (the anti-windup rule of
// ArduPilot's AC_PID_Basic). No allocation, no exceptions.
class PiController {
 public:
  explicit PiController(const PiGains& gains) : gains_(gains) {}

  // Bumpless (re)start: the next output with zero error equals `output`.
  void reset(double output);

  // error = measured - target, in the sense that a positive error must
  // increase the output. dt_s > 0.
  double update(double error, double dt_s);

  double output() const { return output_; }
  double integrator() const { return integrator_; }
  bool saturated() const { return saturated_; }

 private:
  double clamp(double value) const;

  PiGains gains_;
  double integrator_ = 0.0;
  double output_ = 0.0;
  bool saturated_ = false;
};

}  // namespace glider::fw
