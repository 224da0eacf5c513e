// SPDX-License-Identifier: Apache-2.0
// A resumed flight (a forecast starts at the dive, mid-mission) carries the
// glider's mean glide speed over (Navigator::seed_average_speed), so its
// first heading is Slocum's current correction at that speed, not the aim
// point thrown by the first instants of a dive; bad values are refused.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>

#include "glider/firmware/current_correction.hpp"
#include "glider/firmware/navigator.hpp"

using namespace glider;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
const fw::LatLon kStart{54.3, 7.4};

fw::MissionPlan one_waypoint_north() {
  fw::MissionPlan plan;
  plan.waypoint_count = 1;
  plan.waypoints[0] = fw::LocalFrame(kStart).to_global({0.0, 10000.0});
  plan.legs_to_run = fw::kLegsLoopForever;
  return plan;
}

// At the surface with a fix, dive, then one cycle gliding down at `pitch`:
// the heading the navigator asks for on that first cycle under water.
double first_heading(fw::Navigator& nav) {
  fw::NavigatorInputs in;
  in.now_us = 1'000'000;
  in.phase = fw::Phase::kSurface;
  in.segment_complete = true;
  in.fix.latitude_deg = kStart.lat_deg;
  in.fix.longitude_deg = kStart.lon_deg;
  in.fix.quality = 1;
  in.fix.valid = true;
  in.fix.time_us = in.now_us;
  const fw::NavigatorOutputs up = nav.update(in);
  CHECK_TRUE(up.start_segment);
  in.now_us += 1'000'000;
  in.phase = fw::Phase::kDive;
  in.segment_complete = false;
  in.attitude_ok = true;
  in.pitch_rad = -0.05;  // still pitching over: the DR's speed is small
  in.heading_rad = 0.0;
  in.depth_rate_ok = true;
  in.depth_rate_m_s = 0.002;
  return nav.update(in).heading_target_rad;
}

}  // namespace

TEST_GROUP(NavigatorSeededSpeed){};

TEST(NavigatorSeededSpeed, BadValuesAreRefused) {
  fw::Navigator nav(one_waypoint_north(), fw::DeadReckoningConfig{}, 0.0);
  for (double speed : {kNaN, 0.0, -0.3, 3.5, std::numeric_limits<double>::infinity()}) {
    CHECK_FALSE(nav.seed_average_speed(speed, 3600.0));
  }
  for (double glided : {kNaN, 0.0, -1.0, 2e9}) CHECK_FALSE(nav.seed_average_speed(0.3, glided));
  CHECK_TRUE(std::isnan(nav.average_speed_m_s()));
  CHECK_TRUE(nav.seed_average_speed(0.27, 3600.0));
  DOUBLES_EQUAL(0.27, nav.average_speed_m_s(), 1e-12);
}

TEST(NavigatorSeededSpeed, AResumedFlightSteersSlocumsLawFromItsFirstCycle) {
  // 0.2 m/s east across a waypoint 10 km north, the glider's mean glide
  // speed 0.3 m/s: Slocum's aim point is 6667 m west of the waypoint.
  const fw::EastNorth current{0.2, 0.0};
  const double law = fw::aim_point_heading({0.0, 0.0}, {0.0, 10000.0}, current, 0.3);
  fw::Navigator seeded(one_waypoint_north(), fw::DeadReckoningConfig{}, 0.0);
  seeded.seed_current(current);
  CHECK_TRUE(seeded.seed_average_speed(0.3, 3600.0));
  DOUBLES_EQUAL(law, first_heading(seeded), 0.2 * M_PI / 180.0);
  // Without it the first cycle's average is the instant's crawl (the aim
  // point's speed floor, 0.1 m/s): the aim thrown three times as far upstream.
  fw::Navigator unseeded(one_waypoint_north(), fw::DeadReckoningConfig{}, 0.0);
  unseeded.seed_current(current);
  CHECK_TRUE(std::fabs(first_heading(unseeded) - law) > 10.0 * M_PI / 180.0);
}
