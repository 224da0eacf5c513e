// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/time.hpp"

namespace glider::hal {

// The only source of time for the firmware. Monotonic; on Linux it is
// CLOCK_MONOTONIC, in SIL a simulated clock advanced by the scenario runner.
class Clock {
 public:
  virtual ~Clock() = default;
  virtual Micros now_us() const = 0;
};

}  // namespace glider::hal
