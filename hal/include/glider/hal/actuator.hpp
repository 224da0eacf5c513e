// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/time.hpp"

namespace glider::hal {

// What a position-controlled actuator reports back. `fault` is set by the
// driver when the device reports a fault or stops answering; the firmware
// turns it into its abort path.
struct ActuatorReading {
  double position = 0.0;  // in the actuator's unit (cc or in)
  Micros time_us = 0;
  bool valid = false;
  bool fault = false;
};

}  // namespace glider::hal
