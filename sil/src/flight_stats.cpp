// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/flight_stats.hpp"

#include <algorithm>
#include <cmath>

#include "glider/firmware/yo_mission.hpp"
#include "glider/units.hpp"

namespace glider::sil {

bool FlightStats::write(const hal::FlightLogRecord& r) {
  const std::int32_t dive = static_cast<std::int32_t>(fw::Phase::kDive);
  const std::int32_t climb = static_cast<std::int32_t>(fw::Phase::kClimb);
  if (r.m_depth_state != phase_) {
    if (phase_ == dive || phase_ == climb) {
      inflections_.push_back(extreme_depth_);
    }
    phase_ = r.m_depth_state;
    phase_start_us_ = r.time_us;
    extreme_depth_ = std::isfinite(r.m_depth) ? r.m_depth : 0.0;
  }
  yos_ = std::max(yos_, r.x_yo_count);
  segments_ = std::max(segments_, r.x_segment);
  waypoints_reached_ = std::max(waypoints_reached_, r.x_waypoints_reached);
  if (std::isfinite(r.x_dr_error_m)) {
    surfacings_.push_back({hal::to_seconds(r.time_us), r.x_dr_error_m, r.x_dr_distance_m, r.m_water_vx, r.m_water_vy});
  }

  if (std::isfinite(r.m_depth)) {
    max_depth_ = std::max(max_depth_, r.m_depth);
    extreme_depth_ = phase_ == dive ? std::max(extreme_depth_, r.m_depth) : std::min(extreme_depth_, r.m_depth);
  }
  const bool settled = hal::to_seconds(r.time_us - phase_start_us_) >= settle_s_;
  if (settled && (phase_ == dive || phase_ == climb) && std::isfinite(r.m_pitch) && std::isfinite(r.m_depth_rate)) {
    GlideStats& s = phase_ == dive ? dives_ : climbs_;
    ++s.samples;
    s.pitch_sum_rad += r.m_pitch;
    s.depth_rate_sum_m_s += r.m_depth_rate;
    const double degrees = std::clamp(std::round(rad_to_deg(r.m_pitch)), -90.0, 90.0);
    ++s.pitch_histogram_deg[static_cast<std::size_t>(degrees + 90.0)];
    if (std::isfinite(r.c_pitch)) {
      const double error = r.m_pitch - r.c_pitch;
      s.max_pitch_error_rad = std::max(s.max_pitch_error_rad, std::abs(error));
      ++s.pitch_error_samples;
      s.pitch_error_sq_sum_rad2 += error * error;
    }
  }
  return true;
}

}  // namespace glider::sil
