// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/actuator.hpp"

namespace glider::hal {

// Rudder (Slocum: the fin). rad, + turns the glider clockwise (heading up),
// the sign of Slocum's c_fin / m_fin in the real logs.
class Rudder {
 public:
  virtual ~Rudder() = default;
  virtual void command_angle_rad(double angle_rad) = 0;
  virtual ActuatorReading read_angle_rad() = 0;
};

}  // namespace glider::hal
