// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/actuator.hpp"

namespace glider::hal {

// Buoyancy engine. Slocum's unit and sign: cc, + = more buoyant (water out).
class BuoyancyPump {
 public:
  virtual ~BuoyancyPump() = default;
  virtual void command_volume_cc(double volume_cc) = 0;
  virtual ActuatorReading read_volume_cc() = 0;
};

}  // namespace glider::hal
