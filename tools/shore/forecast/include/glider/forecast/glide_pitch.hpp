// SPDX-License-Identifier: Apache-2.0
#pragma once
// The pitch of a steady glide, dives and climbs apart: what the speed term
// (speed_term.hpp) compares between the glider's logged m_pitch and the
// model's own flight to read the glider's pitch sensor calibration. One rule
// for both, so the two means are of the same samples: deeper than 3 m,
// moving vertically faster than 5 cm/s, pitched more than 10 deg the way it
// moves (nose down diving), and the pitch changing by less than 0.3 deg/s
// (not an inflection, not a pump or battery move).
#include <algorithm>
#include <cmath>

namespace glider::forecast {

struct GlidePitch {
  double dive_sum_rad = 0.0, dive_sum2_rad2 = 0.0;  // of |pitch|
  double climb_sum_rad = 0.0, climb_sum2_rad2 = 0.0;
  // |depth rate| (m/s) of the same samples: the depth-rate calibration's
  // (depth_rate_calibration.hpp).
  double dive_rate_sum_m_s = 0.0, climb_rate_sum_m_s = 0.0;
  int dive_n = 0, climb_n = 0;

  static constexpr double kMinDepthM = 3.0, kMinDepthRateMS = 0.05, kMinPitchRad = 0.1745, kMaxPitchRateRadS = 0.005;

  // One sample: depth (m, + down), depth rate (m/s, + descending), pitch
  // (rad, + nose up) and its rate (rad/s). Not finite: not counted.
  void add(double depth_m, double depth_rate_m_s, double pitch_rad, double pitch_rate_rad_s) {
    if (!(depth_m > kMinDepthM) || !(std::fabs(pitch_rate_rad_s) < kMaxPitchRateRadS)) return;
    if (!(std::fabs(pitch_rad) > kMinPitchRad) || !(std::fabs(depth_rate_m_s) > kMinDepthRateMS)) return;
    const double p = std::fabs(pitch_rad);
    if (pitch_rad < 0.0 && depth_rate_m_s > 0.0) {
      dive_sum_rad += p;
      dive_sum2_rad2 += p * p;
      dive_rate_sum_m_s += depth_rate_m_s;
      ++dive_n;
    } else if (pitch_rad > 0.0 && depth_rate_m_s < 0.0) {
      climb_sum_rad += p;
      climb_sum2_rad2 += p * p;
      climb_rate_sum_m_s -= depth_rate_m_s;
      ++climb_n;
    }
  }
  double dive_rad() const { return dive_n > 0 ? dive_sum_rad / dive_n : std::nan(""); }
  double climb_rad() const { return climb_n > 0 ? climb_sum_rad / climb_n : std::nan(""); }
  double dive_rate_m_s() const { return dive_n > 0 ? dive_rate_sum_m_s / dive_n : std::nan(""); }
  double climb_rate_m_s() const { return climb_n > 0 ? climb_rate_sum_m_s / climb_n : std::nan(""); }
  double dive_sd_rad() const { return sd(dive_sum_rad, dive_sum2_rad2, dive_n); }
  double climb_sd_rad() const { return sd(climb_sum_rad, climb_sum2_rad2, climb_n); }

 private:
  static double sd(double sum, double sum2, int n) {
    if (n < 2) return std::nan("");
    const double mean = sum / n;
    return std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  }
};

}  // namespace glider::forecast
