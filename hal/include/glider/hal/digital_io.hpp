// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/time.hpp"

namespace glider::hal {

// One digital line, in the logical sense (`active` = asserted: leak present,
// limit reached, burn wire on). Active-low wiring and bias are the driver's
// business (board file), never the firmware's.
struct DigitalSample {
  bool active = false;
  Micros time_us = 0;
  bool valid = false;  // false: driver fault, line not readable
};

class DigitalInput {
 public:
  virtual ~DigitalInput() = default;
  // Non-blocking. Implementations with edge events latch an edge so that a
  // pulse shorter than one control cycle is still seen once.
  virtual DigitalSample read() = 0;
};

class DigitalOutput {
 public:
  virtual ~DigitalOutput() = default;
  // Non-blocking. Returns false when the driver could not set the line.
  virtual bool set(bool active) = 0;
};

}  // namespace glider::hal
