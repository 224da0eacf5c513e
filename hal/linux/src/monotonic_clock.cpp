// SPDX-License-Identifier: Apache-2.0
#include <time.h>

#include "glider/hal_linux/modbus_actuators.hpp"

namespace glider::hal_linux {

hal::Micros MonotonicClock::now_us() const {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<hal::Micros>(t.tv_sec) * hal::kMicrosPerSecond + t.tv_nsec / 1000;
}

}  // namespace glider::hal_linux
