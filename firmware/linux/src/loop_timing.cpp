// SPDX-License-Identifier: Apache-2.0
#include "glider/target/loop_timing.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace glider::target {

void LoopTiming::record(hal::Micros lateness_us, hal::Micros cycle_us, hal::Micros period_us) {
  const hal::Micros late = std::max<hal::Micros>(lateness_us, 0);
  const auto bucket = std::min<std::size_t>(std::bit_width(static_cast<std::uint64_t>(late)), kBuckets - 1);
  ++histogram_[bucket];
  ++cycles_;
  sum_lateness_us_ += static_cast<double>(late);
  max_lateness_us_ = std::max(max_lateness_us_, late);
  max_cycle_us_ = std::max(max_cycle_us_, cycle_us);
  if (late + cycle_us > period_us) ++overruns_;
}

hal::Micros LoopTiming::lateness_quantile_us(double q) const {
  const auto wanted = static_cast<std::uint64_t>(std::llround(q * static_cast<double>(cycles_)));
  std::uint64_t seen = 0;
  for (std::size_t i = 0; i < kBuckets; ++i) {
    seen += histogram_[i];
    if (seen >= wanted && seen > 0) return i == 0 ? 0 : (hal::Micros{1} << i) - 1;
  }
  return max_lateness_us_;
}

int LoopTiming::format(char* out, std::size_t size) const {
  return std::snprintf(out, size,
                       "cycles %llu, wake-up late mean %.0f us, p50 <= %lld us, p99 <= %lld us, max %lld us; "
                       "work max %lld us; overruns %llu",
                       static_cast<unsigned long long>(cycles_), mean_lateness_us(),
                       static_cast<long long>(lateness_quantile_us(0.5)),
                       static_cast<long long>(lateness_quantile_us(0.99)), static_cast<long long>(max_lateness_us_),
                       static_cast<long long>(max_cycle_us_), static_cast<unsigned long long>(overruns_));
}

}  // namespace glider::target
