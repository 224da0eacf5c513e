// SPDX-License-Identifier: Apache-2.0
#pragma once
// The depth-averaged current over the next dive, from the glider's own
// per-segment estimates (m_water_vx/vy after each surfacing: Slocum's, and
// this firmware's, update from the dead-reckoning error), with an
// uncertainty. Three rules, each used only where the history allows it:
//   mean + M2 tide (12.42 h) fitted by least squares (>= 5 estimates over
//     >= 9 h of the last day), averaged over the coming window;
//   a straight line in time (>= 3 estimates over >= 1.5 h of the last 6 h,
//     the recent weighted more), at the window's middle;
//   persistence: the last estimate.
// Each predicts the last day's estimates from the ones before them; a fitted
// rule replaces persistence only if it did better on the same cases (two at
// least), and the winner's hindcast error is the uncertainty.
// The baseline ("the last depth-averaged current persists") is the last one.
#include <string>
#include <vector>

namespace glider::forecast {

struct CurrentSample {
  double utc_s = 0.0;  // middle of the segment it was measured over
  double east_m_s = 0.0;
  double north_m_s = 0.0;
  double span_s = 0.0;  // the segment it is the mean over (0: a point in time)
};

struct CurrentEstimate {
  double east_m_s = 0.0;
  double north_m_s = 0.0;
  double sigma_east_m_s = 0.2;  // 1 sigma of the window's mean current
  double sigma_north_m_s = 0.2;
  std::string method;  // "tidal fit", "trend", "last", "none"
  int samples = 0;
};

struct TidalPrior;

// The mean current over [from_utc_s, to_utc_s]; `prior` is the tidal prior
// the fourth rule and the first estimates use (tidal_prior.hpp; its mode off:
// persistence instead).
CurrentEstimate estimate_current(const std::vector<CurrentSample>& samples, double from_utc_s, double to_utc_s,
                                 const TidalPrior& prior);
CurrentEstimate estimate_current(const std::vector<CurrentSample>& samples, double from_utc_s, double to_utc_s);

// The last sample (zero with a wide sigma when there is none).
CurrentEstimate last_current(const std::vector<CurrentSample>& samples);
// The same with `floor` (m/s) the least sigma when there are two or more.
CurrentEstimate last_current(const std::vector<CurrentSample>& samples, double floor);

}  // namespace glider::forecast
