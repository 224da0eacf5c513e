// SPDX-License-Identifier: Apache-2.0
#pragma once
// The depth-averaged current over the next dive, from the glider's own
// per-segment estimates (m_water_vx/vy after each surfacing: Slocum's, and
// this firmware's, update from the dead-reckoning error), with an
// uncertainty. Three rules by how much history there is:
//   >= 8 estimates over >= 12 h: mean + M2 tide (12.42 h) fitted by least
//     squares, evaluated over the coming window;
//   >= 3 estimates over >= 1.5 h in the last 6 h: a straight line in time
//     (weighted to the recent), extrapolated to the window's middle;
//   otherwise: the last estimate.
// The baseline ("the last depth-averaged current persists") is the last one.
#include <string>
#include <vector>

namespace glider::forecast {

struct CurrentSample {
  double utc_s = 0.0;  // middle of the segment it was measured over
  double east_m_s = 0.0;
  double north_m_s = 0.0;
};

struct CurrentEstimate {
  double east_m_s = 0.0;
  double north_m_s = 0.0;
  double sigma_east_m_s = 0.2;  // 1 sigma of the window's mean current
  double sigma_north_m_s = 0.2;
  std::string method;  // "tidal fit", "trend", "last", "none"
  int samples = 0;
};

// The mean current over [from_utc_s, to_utc_s].
CurrentEstimate estimate_current(const std::vector<CurrentSample>& samples, double from_utc_s, double to_utc_s);

// The last sample (zero with a wide sigma when there is none).
CurrentEstimate last_current(const std::vector<CurrentSample>& samples);

}  // namespace glider::forecast
