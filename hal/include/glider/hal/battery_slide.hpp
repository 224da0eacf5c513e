// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/actuator.hpp"

namespace glider::hal {

// Pitch battery slide. Slocum's unit and sign: in, + = forward (nose down).
class BatterySlide {
 public:
  virtual ~BatterySlide() = default;
  virtual void command_position_in(double position_in) = 0;
  virtual ActuatorReading read_position_in() = 0;
};

}  // namespace glider::hal
