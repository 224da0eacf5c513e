// SPDX-License-Identifier: Apache-2.0
#pragma once
// The truth's sensors: coloured noise (AR(1) in continuous time: correlation
// time and standard deviation) and quantization, per logged channel. Levels
// fitted to the real comet logs' residuals (fit_noise.py; numbers and how
// in sensors.cpp).
#include <random>

namespace glider::truth {

// x(t + dt) = phi x(t) + sqrt(1 - phi^2) sigma e, phi = exp(-dt / tau):
// stationary with standard deviation sigma at any sampling interval.
class Ar1 {
 public:
  Ar1(double sigma, double correlation_s) : sigma_(sigma), tau_(correlation_s) {}
  double next(double dt_s, std::mt19937_64& rng);
  double sigma() const { return sigma_; }
  double correlation_s() const { return tau_; }

 private:
  double sigma_, tau_, x_ = 0.0;
  bool started_ = false;
};

double quantize(double x, double step);

struct SensorNoise {
  Ar1 depth_m, pitch_rad, roll_rad, heading_rad;
  double depth_step_m, angle_step_rad, battpos_step_in, ballast_step_cc;
  static SensorNoise slocum();
};

}  // namespace glider::truth
