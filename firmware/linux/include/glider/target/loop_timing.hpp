// SPDX-License-Identifier: Apache-2.0
#pragma once
// Wake-up jitter and overrun statistics of the fixed-step loop: fixed-size
// (a log2 histogram), no allocation, printable as one line for the log.
#include <array>
#include <cstdint>
#include <cstdio>

#include "glider/hal/time.hpp"

namespace glider::target {

class LoopTiming {
 public:
  // `lateness_us`: wake-up time minus the cycle's absolute deadline (>= 0
  // normally; timerfd never wakes early). `cycle_us`: how long the cycle's
  // work took. `period_us`: the cycle period.
  void record(hal::Micros lateness_us, hal::Micros cycle_us, hal::Micros period_us);

  std::uint64_t cycles() const { return cycles_; }
  std::uint64_t overruns() const { return overruns_; }  // work + lateness past the period
  hal::Micros max_lateness_us() const { return max_lateness_us_; }
  double mean_lateness_us() const { return cycles_ ? sum_lateness_us_ / static_cast<double>(cycles_) : 0.0; }
  // Upper bound of the histogram bucket holding the q-quantile (0..1).
  hal::Micros lateness_quantile_us(double q) const;
  hal::Micros max_cycle_us() const { return max_cycle_us_; }

  // "cycles N, wake-up late mean X us, p99 <= Y us, max Z us, work max W us, overruns K"
  int format(char* out, std::size_t size) const;

 private:
  static constexpr std::size_t kBuckets = 32;  // bucket i: lateness < 2^i us
  std::array<std::uint64_t, kBuckets> histogram_{};
  std::uint64_t cycles_ = 0;
  std::uint64_t overruns_ = 0;
  double sum_lateness_us_ = 0.0;
  hal::Micros max_lateness_us_ = 0;
  hal::Micros max_cycle_us_ = 0;
};

}  // namespace glider::target
