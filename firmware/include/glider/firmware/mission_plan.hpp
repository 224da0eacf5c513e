// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a mission file becomes: the horizontal plan (waypoints, segments,
// surfacing) and the abort limits beyond the yo's own envelope. Fixed size,
// so the flight software holds it without a heap.
#include <array>
#include <cstdint>
#include <limits>

#include "glider/firmware/geo.hpp"

namespace glider::fw {

constexpr std::size_t kMaxWaypoints = 32;

// Slocum goto_list num_legs_to_run: -1 loop the list forever, -2 once
// through it, n > 0 that many waypoints.
constexpr std::int32_t kLegsLoopForever = -1;
constexpr std::int32_t kLegsOnce = -2;

struct MissionPlan {
  std::array<LatLon, kMaxWaypoints> waypoints{};
  std::int32_t waypoint_count = 0;   // 0: no navigation (fly `heading_rad` or none)
  double waypoint_radius_m = 100.0;  // goto_list list_when_wpt_dist
  std::int32_t legs_to_run = kLegsOnce;
  // Segment: dive from the surface, yos, surface. It ends after
  // `yos_per_segment` yos, or when `surface_interval_s` has passed since the
  // previous such end (surface start_when 9, every when_secs: Slocum counts
  // from its previous firing, not the arrival nor the dive), or `no_comms_interval_s` since the last
  // call connected (start_when 12), whichever first; <= 0 = no limit.
  double surface_interval_s = 0.0;
  double no_comms_interval_s = 0.0;
  // A fixed heading (set_heading) when there are no waypoints; NaN = none,
  // the fin is held centred.
  double heading_rad = std::numeric_limits<double>::quiet_NaN();
  // At the surface: wait this long at most for a GPS fix (gps_wait_time),
  // and stay at least `surface_dwell_s` (keystroke_wait_time: the pilot's
  // chance to call in) before the next dive. 0 (a TOML yo mission): the
  // mission ends as soon as it is up.
  double gps_wait_s = 0.0;
  double surface_dwell_s = 0.0;
  bool current_correction = true;  // u_use_current_correction
  // The surface dialog is re-printed this often during a call (printout_cycle_time).
  double printout_cycle_s = 60.0;
};

// Abort limits of the abend behaviour; <= 0 disables a limit (as in Slocum),
// except the overdepth and overtime limits, which live in YoMissionConfig.
struct AbortLimits {
  double samedepth_for_s = 0.0;   // depth stays within samedepth_band_m this long under water
  double samedepth_band_m = 1.0;  // (not a Slocum argument; documented in docs/missions.md)
  double stalled_for_s = 0.0;     // gliding slower than stalled_depth_rate_m_s this long
  double stalled_depth_rate_m_s = 0.03;
  double max_wpt_distance_m = 0.0;  // a GPS fix farther than this from the active waypoint
  double remaining_charge_min_pct = 0.0;
  double battery_capacity_amphr = 150.0;  // for the remaining charge (f_coulomb_battery_capacity)
  bool drop_weight_fitted = false;
};

}  // namespace glider::fw
