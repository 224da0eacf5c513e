// SPDX-License-Identifier: Apache-2.0
#pragma once
// Time in the firmware is an integer count of microseconds from the HAL clock.
// Integers (not doubles) so that SIL runs are bit-for-bit reproducible and a
// month-long mission (2.6e12 us) keeps full resolution.
#include <cstdint>

namespace glider::hal {

using Micros = std::int64_t;

constexpr Micros kMicrosPerSecond = 1'000'000;

constexpr double to_seconds(Micros t) { return static_cast<double>(t) * 1e-6; }

}  // namespace glider::hal
