// SPDX-License-Identifier: Apache-2.0
#pragma once
// The clock the flight loop runs on: CLOCK_MONOTONIC (never steps, so a GPS
// or NTP correction of the wall clock cannot stretch or skip a cycle), or on
// a bench/HIL rig CLOCK_MONOTONIC running `scale` times faster from start-up
// (glider-firmware --time-scale X, refused unless the board file says
// `bench = true`). Every device timestamp and every deadline is in this time.
#include "glider/hal/clock.hpp"

namespace glider::target {

hal::Micros monotonic_now_us();

class LoopClock final : public hal::Clock {
 public:
  explicit LoopClock(double scale = 1.0);

  hal::Micros now_us() const override;
  // The CLOCK_MONOTONIC instant at which the loop clock reads `loop_us`
  // (where the timerfd is armed).
  hal::Micros to_monotonic_us(hal::Micros loop_us) const;
  double scale() const { return scale_; }

 private:
  double scale_;
  hal::Micros origin_us_;  // monotonic time of construction: both clocks agree there
};

}  // namespace glider::target
