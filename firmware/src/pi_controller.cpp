// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/pi_controller.hpp"

#include <algorithm>

namespace glider::fw {

double PiController::clamp(double value) const { return std::clamp(value, gains_.out_min, gains_.out_max); }

void PiController::reset(double output) {
  integrator_ = clamp(output);
  output_ = integrator_;
  saturated_ = false;
}

double PiController::update(double error, double dt_s) {
  const double proportional = gains_.kp * error;
  const double increment = gains_.ki * error * dt_s;
  const double unclamped = proportional + integrator_ + increment;
  const bool over_max = unclamped > gains_.out_max;
  const bool under_min = unclamped < gains_.out_min;
  // Integrate unless that would drive an already saturated output further.
  if (!(over_max && increment > 0.0) && !(under_min && increment < 0.0)) {
    integrator_ += increment;
  }
  // Keep the integrator itself inside the actuator range so that it can never
  // hold the output against a limit after the error changes sign.
  integrator_ = clamp(integrator_);
  const double raw = proportional + integrator_;
  output_ = clamp(raw);
  saturated_ = raw != output_;
  return output_;
}

}  // namespace glider::fw
