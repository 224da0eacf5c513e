// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/time.hpp"

namespace glider::hal {

// Slocum conventions: pitch + nose up, roll + starboard wing down,
// heading true, 0 = north, clockwise, in [0, 2 pi). Euler angles as a
// compass gives them: pitch in [-pi/2, pi/2], roll in [-pi, pi]; the
// firmware takes a sample outside these ranges as invalid.
struct AttitudeSample {
  double pitch_rad = 0.0;
  double roll_rad = 0.0;
  double heading_rad = 0.0;
  Micros time_us = 0;
  bool valid = false;
};

class AttitudeSensor {
 public:
  virtual ~AttitudeSensor() = default;
  virtual AttitudeSample read() = 0;
};

}  // namespace glider::hal
