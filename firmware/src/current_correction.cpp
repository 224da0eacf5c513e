// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/current_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glider::fw {

double aim_point_heading(EastNorth from, EastNorth target, EastNorth current_m_s, double average_speed_m_s) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const bool finite = std::isfinite(from.east_m) && std::isfinite(from.north_m) && std::isfinite(target.east_m) &&
                      std::isfinite(target.north_m) && std::isfinite(current_m_s.east_m) &&
                      std::isfinite(current_m_s.north_m) && std::isfinite(average_speed_m_s);
  if (!finite || !(average_speed_m_s > 0.0)) return kNaN;
  const double time_to_go_s = distance_m(from, target) / std::max(kMinAimSpeedMps, average_speed_m_s);
  const EastNorth aim{target.east_m - current_m_s.east_m * time_to_go_s,
                      target.north_m - current_m_s.north_m * time_to_go_s};
  // On the waypoint itself (or an aim point exactly there) atan2 would say
  // north for nothing: the caller's bearing is as good as any.
  if (!(distance_m(from, aim) > 0.0)) return kNaN;
  return bearing_rad(from, aim);
}

}  // namespace glider::fw
