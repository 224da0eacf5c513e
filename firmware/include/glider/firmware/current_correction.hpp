// SPDX-License-Identifier: Apache-2.0
#pragma once
// Slocum's goto current correction: steer at the waypoint moved upstream by
// the depth-averaged current times the time to get there at the average
// speed through the water. It reproduces a real Slocum's logged c_heading
// to 0.01 deg median on comet-2016 and comet-2019 (benchmarks/
// heading_law_real.py); a crab angle asin(c_perp / U) was 9-21 deg off and,
// when the current outruns the glider, turns it into the current instead of
// towards the waypoint.
#include "glider/firmware/geo.hpp"

namespace glider::fw {

// Below this the time to the waypoint is counted at this speed (glidersim's
// emulation of the law floors m_speed at 0.1 m/s): a stalled average must
// not throw the aim point to infinity.
inline constexpr double kMinAimSpeedMps = 0.1;

// Heading (rad, 0 north, clockwise, [0, 2 pi)) from `from` towards
// target - current * |target - from| / max(kMinAimSpeedMps, average speed).
// NaN when an input is not finite or the average speed is not positive (the
// caller then steers the plain bearing).
double aim_point_heading(EastNorth from, EastNorth target, EastNorth current_m_s, double average_speed_m_s);

}  // namespace glider::fw
