// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a bench move measured: from the sampled positions of one move,
// rise time, overshoot, settling time and rate. Pure computation.
#include <cstdint>
#include <vector>

namespace glider::bench {

struct Sample {
  double time_s = 0.0;
  double position = 0.0;
  double speed = 0.0;
  std::uint16_t status = 0;
  std::uint16_t fault_code = 0;
};

struct MoveMetrics {
  double travel_time_s = 0.0;  // command to in-position
  double rise_time_s = 0.0;    // 10 % to 90 % of the step
  double overshoot_pct = 0.0;  // beyond the target, % of the step
  double settle_time_s = 0.0;  // last entry into the 2 % band
  double mean_rate = 0.0;      // between 10 % and 90 %, unit/s
};

// `samples` from the command (t = 0) to the end of the move.
MoveMetrics measure_move(const std::vector<Sample>& samples, double start, double target);

}  // namespace glider::bench
