// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/hal/clock.hpp"

namespace glider::sil {

// Lockstep clock: time moves only when the scenario runner advances it, so a
// SIL run is as fast as the CPU allows and identical on every run.
class SimClock final : public hal::Clock {
 public:
  hal::Micros now_us() const override { return now_us_; }
  void advance(hal::Micros dt_us) { now_us_ += dt_us; }

 private:
  hal::Micros now_us_ = 0;
};

}  // namespace glider::sil
