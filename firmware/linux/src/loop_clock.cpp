// SPDX-License-Identifier: Apache-2.0
#include "glider/target/loop_clock.hpp"

#include <cmath>
#include <ctime>

namespace glider::target {

hal::Micros monotonic_now_us() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<hal::Micros>(t.tv_sec) * hal::kMicrosPerSecond + t.tv_nsec / 1000;
}

LoopClock::LoopClock(double scale) : scale_(scale), origin_us_(monotonic_now_us()) {}

hal::Micros LoopClock::now_us() const {
  const hal::Micros now = monotonic_now_us();
  if (scale_ == 1.0) return now;
  return origin_us_ + std::llround(static_cast<double>(now - origin_us_) * scale_);
}

hal::Micros LoopClock::to_monotonic_us(hal::Micros loop_us) const {
  if (scale_ == 1.0) return loop_us;
  return origin_us_ + std::llround(static_cast<double>(loop_us - origin_us_) / scale_);
}

}  // namespace glider::target
