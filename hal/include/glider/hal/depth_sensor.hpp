// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/time.hpp"

namespace glider::hal {

struct DepthSample {
  double depth_m = 0.0;  // positive down
  Micros time_us = 0;    // when the value was measured
  bool valid = false;    // false: no reading, out of range or driver fault
};

class DepthSensor {
 public:
  virtual ~DepthSensor() = default;
  virtual DepthSample read() = 0;
};

}  // namespace glider::hal
