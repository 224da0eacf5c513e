// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/sensors.hpp"

#include <cmath>

namespace glider::truth {

double Ar1::next(double dt_s, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  if (!started_ || tau_ <= 0.0) {
    started_ = true;
    x_ = sigma_ * normal(rng);
    return x_;
  }
  const double phi = std::exp(-dt_s / tau_);
  x_ = phi * x_ + std::sqrt(1.0 - phi * phi) * sigma_ * normal(rng);
  return x_;
}

double quantize(double x, double step) { return step > 0.0 ? step * std::round(x / step) : x; }

// From `python3 tools/science/truth/fit_noise.py tests/data/real/comet-2016-174-05.csv
// tests/data/real/comet-2019-222-02-154.csv`: on the glides, the residual of
// a 7-row local quadratic (4.3-4.5 s rows) has
//   m_depth   sigma 0.069 / 0.086 m, lag-1 -0.42 / -0.40, step 0.025 m
//   m_pitch   sigma 0.013 / 0.018 rad, lag-1 +0.11 / +0.10, step 0.1 deg
//   m_roll    sigma 0.0025 / 0.0088 rad, lag-1 -0.35 / -0.44, step 0.1 deg
//   m_heading sigma 0.016 / 0.020 rad, lag-1 -0.32 / -0.30, step 0.1 deg
// Through this filter white noise gives lag-1 -0.49 and keeps 66 % of its
// variance; AR(1) with phi 0.2 per row gives -0.43 (53 %), phi 0.6 -0.38.
// Depth: phi 0.2 per 4.4 s row (correlation 4.4 / ln 5 = 2.7 s), sigma
// 0.07 m. Roll: phi ~0.5 per row (6 s), sigma 0.005 rad. Heading and
// pitch: their lag-1 (-0.31, +0.1) is above anything AR(1) noise gives
// through the filter (-0.49 for white, never above -0.36): it is slow real
// motion, not sensor noise. The sensor keeps a white part (sigma 0.01 rad,
// 1 s); the heading's slow part is the dynamics' yaw disturbance
// (flight.cpp), the pitch's the controllers' own motion.
SensorNoise SensorNoise::slocum() {
  constexpr double kDeg = 0.017453292519943295;
  return SensorNoise{Ar1(0.07, 2.7), Ar1(0.01, 1.0), Ar1(0.005, 6.0), Ar1(0.01, 1.0),
                     0.025,          0.1 * kDeg,     0.0013577,       0.3092};
}

}  // namespace glider::truth
