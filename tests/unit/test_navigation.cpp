// SPDX-License-Identifier: Apache-2.0
// The fin autopilot, dead reckoning, the navigator and the abort monitor,
// each on scripted inputs.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <numbers>

#include "glider/firmware/abort_monitor.hpp"
#include "glider/firmware/dead_reckoning.hpp"
#include "glider/firmware/heading_controller.hpp"
#include "glider/firmware/navigator.hpp"
#include "glider/units.hpp"

using namespace glider;
using namespace glider::fw;

TEST_GROUP(HeadingController){};

TEST(HeadingController, ProportionalLawIsPaper001sKp) {
  HeadingControlConfig c;
  c.law = HeadingLaw::kProportional;
  HeadingController h(c);
  DOUBLES_EQUAL(0.5 * deg_to_rad(10.0), h.update(deg_to_rad(80.0), deg_to_rad(90.0), 1.0), 1e-12);
  // The shorter way round: 350 -> 10 deg is +20 deg, saturated at the fin limit.
  DOUBLES_EQUAL(std::min(0.5 * deg_to_rad(20.0), c.fin_max_rad), h.update(deg_to_rad(350.0), deg_to_rad(10.0), 1.0),
                1e-12);
}

TEST(HeadingController, SlocumLawIntegratesWithoutLimitWhileSaturated) {
  HeadingControlConfig c;
  c.law = HeadingLaw::kSlocum;
  HeadingController h(c);
  for (int i = 0; i < 100; ++i) h.update(0.0, deg_to_rad(60.0), 1.0);  // held off course: saturated
  DOUBLES_EQUAL(c.fin_max_rad, h.fin(), 1e-12);
  CHECK(h.integrator() > 1.5);  // wound up far beyond the fin's travel
}

TEST(HeadingController, CompensatedLawOnlyUnwindsWhileSaturated) {
  HeadingControlConfig c;
  c.law = HeadingLaw::kCompensated;
  HeadingController h(c);
  for (int i = 0; i < 100; ++i) h.update(0.0, deg_to_rad(60.0), 1.0);
  CHECK(h.integrator() <= c.fin_max_rad);
  const double wound = h.integrator();
  for (int i = 0; i < 5; ++i) h.update(0.0, deg_to_rad(60.0), 1.0);
  CHECK(h.integrator() <= wound + 1e-12);  // saturated: never further out
}

TEST(HeadingController, CompensatedLawNeverOutrunsTheServo) {
  HeadingControlConfig c;
  c.law = HeadingLaw::kCompensated;
  c.fin_rate_rad_s = 0.05;
  HeadingController h(c);
  const double first = h.update(0.0, deg_to_rad(40.0), 1.0);
  DOUBLES_EQUAL(0.05, first, 1e-12);
  DOUBLES_EQUAL(0.10, h.update(0.0, deg_to_rad(40.0), 1.0), 1e-12);
}

TEST(HeadingController, CompensatedLawLearnsTheFinARollOffsetNeeds) {
  // A vehicle that turns unless the fin holds -0.1 rad: the integrator
  // takes that over, the heading error goes to zero.
  HeadingControlConfig c;
  c.law = HeadingLaw::kCompensated;
  HeadingController h(c);
  double heading = 0.0;
  for (int i = 0; i < 3000; ++i) {
    const double fin = h.update(heading, 0.0, 1.0);
    heading += 0.05 * (fin + 0.1);  // yaw rate of a fin offset by the roll
  }
  DOUBLES_EQUAL(0.0, wrap_pi(heading), deg_to_rad(0.6));
  DOUBLES_EQUAL(-0.1, h.integrator(), 0.01);
}

TEST_GROUP(DeadReckoning){};

TEST(DeadReckoning, SpeedFromDepthRateAndPitchPlusAlpha) {
  DeadReckoningConfig c;
  c.assumed_alpha_rad = deg_to_rad(3.0);
  DeadReckoning dr(c);
  // Diving at -25 deg pitch, 0.2 m/s: glide path 28 deg.
  DOUBLES_EQUAL(0.2 / std::tan(deg_to_rad(28.0)), dr.horizontal_speed(deg_to_rad(-25.0), 0.2), 1e-12);
  DOUBLES_EQUAL(0.0, dr.horizontal_speed(deg_to_rad(-5.0), 0.2), 0.0);  // inflecting
  DOUBLES_EQUAL(0.0, dr.horizontal_speed(deg_to_rad(25.0), 0.2), 0.0);  // nose up but sinking
  dr.reset({100.0, 200.0});
  dr.update(deg_to_rad(-25.0), std::numbers::pi / 2.0, 0.2, {0.0, 0.1}, 10.0);  // east, current north
  DOUBLES_EQUAL(100.0 + 10.0 * 0.2 / std::tan(deg_to_rad(28.0)), dr.position().east_m, 1e-9);
  DOUBLES_EQUAL(201.0, dr.position().north_m, 1e-9);
}

TEST(DeadReckoning, FlightModelTableInterpolatesByPitch) {
  DeadReckoningConfig c;
  c.method = DrMethod::kFlightModel;
  for (std::size_t i = 0; i < c.dive_alpha_rad.size(); ++i) {
    c.dive_alpha_rad[i] = 0.01 * static_cast<double>(i);
    c.climb_alpha_rad[i] = 0.5;
  }
  DeadReckoning dr(c);
  DOUBLES_EQUAL(0.025, dr.alpha_for(-(c.table_first_pitch_rad + 2.5 * c.table_step_rad)), 1e-9);
  DOUBLES_EQUAL(0.5, dr.alpha_for(0.3), 1e-12);
  DOUBLES_EQUAL(0.6, dr.alpha_for(-1.5), 1e-12);  // beyond the table: its last entry
}

TEST_GROUP(Navigator){};

namespace {

hal::GpsFix fix_at(const LocalFrame& frame, EastNorth p, hal::Micros t) {
  const LatLon ll = frame.to_global(p);
  return {ll.lat_deg, ll.lon_deg, 1, 8, 1.0, t, true};
}

}  // namespace

TEST(Navigator, CurrentFromTheDrErrorAndTheAimPointUpstreamOfTheWaypoint) {
  const LocalFrame frame({54.0, 7.0});
  MissionPlan plan;
  plan.waypoint_count = 1;
  plan.waypoints[0] = frame.to_global({0.0, 10000.0});  // 10 km north
  plan.waypoint_radius_m = 100.0;
  DeadReckoningConfig dr;
  dr.assumed_alpha_rad = 0.0;
  Navigator nav(plan, dr, 0.0);
  NavigatorInputs in;
  in.segment_complete = true;
  in.attitude_ok = in.depth_rate_ok = true;
  in.fix = fix_at(frame, {0.0, 0.0}, 0);
  NavigatorOutputs out = nav.update(in);  // launch fix, no waits: dive
  CHECK_TRUE(out.start_segment);
  // 1000 s under water heading north at 0.3 m/s through the water while a
  // 0.1 m/s current sets east.
  in.segment_complete = false;
  in.phase = Phase::kDive;
  in.pitch_rad = -std::atan(1.0);
  in.depth_rate_m_s = 0.3;  // 45 deg: 0.3 m/s horizontal
  in.heading_rad = 0.0;
  for (int t = 1; t <= 1000; ++t) {
    in.now_us = t * hal::kMicrosPerSecond;
    out = nav.update(in);
    DOUBLES_EQUAL(0.0, out.heading_target_rad, 1e-9);  // no current known yet
  }
  in.phase = Phase::kSurface;
  in.segment_complete = true;
  in.now_us = 1001 * hal::kMicrosPerSecond;
  in.fix = fix_at(frame, {100.0, 300.0}, in.now_us);
  out = nav.update(in);
  CHECK_TRUE(out.surfacing.valid);
  DOUBLES_EQUAL(100.0, out.surfacing.dr_error_m, 0.5);
  DOUBLES_EQUAL(0.1, nav.current_m_s().east_m, 0.002);
  DOUBLES_EQUAL(0.0, nav.current_m_s().north_m, 0.002);
  CHECK_TRUE(out.start_segment);
  in.phase = Phase::kDive;
  in.segment_complete = false;
  in.now_us += hal::kMicrosPerSecond;
  out = nav.update(in);
  // Slocum's law: the DR is at (100.1, 300.3) (the fix, then one second
  // north at 0.3 m/s and east with the current), the waypoint 9700 m away,
  // 32 334 s at the average 0.3 m/s; the current (100 m over 1001 s:
  // 0.0999 m/s east) moves the aim 3230 m west: atan2(-3330, 9700) = 18.95
  // deg west of north (the crab law it replaced: asin(1/3) = 19.47 deg).
  DOUBLES_EQUAL(0.3, nav.average_speed_m_s(), 1e-12);
  DOUBLES_EQUAL(5.952458, out.heading_target_rad, 1e-4);
}

TEST(Navigator, WaypointReachedByTheFixAdvancesAndTheListEnds) {
  const LocalFrame frame({54.0, 7.0});
  MissionPlan plan;
  plan.waypoint_count = 2;
  plan.waypoints[0] = frame.to_global({0.0, 50.0});
  plan.waypoints[1] = frame.to_global({0.0, 5000.0});
  plan.legs_to_run = 1;
  Navigator nav(plan, {}, 0.0);
  NavigatorInputs in;
  in.segment_complete = true;
  in.fix = fix_at(frame, {0.0, 0.0}, 0);
  const NavigatorOutputs out = nav.update(in);  // the launch fix is inside the first waypoint's radius
  LONGS_EQUAL(1, nav.waypoints_reached());
  CHECK_TRUE(out.mission_complete);  // one leg asked for: done, stays up
  CHECK_FALSE(out.start_segment);
}

TEST(Navigator, AFixTooFarFromTheWaypointAborts) {
  const LocalFrame frame({54.0, 7.0});
  MissionPlan plan;
  plan.waypoint_count = 1;
  plan.waypoints[0] = frame.to_global({0.0, 50000.0});
  Navigator nav(plan, {}, 20000.0);
  NavigatorInputs in;
  in.segment_complete = true;
  in.fix = fix_at(frame, {0.0, 0.0}, 0);
  CHECK(nav.update(in).abort == AbortCause::kWaypointTooFar);
}

TEST(Navigator, NoFixNoDiveWhenThereAreWaypoints) {
  MissionPlan plan;
  plan.waypoint_count = 1;
  plan.gps_wait_s = 10.0;
  Navigator nav(plan, {}, 0.0);
  NavigatorInputs in;
  in.segment_complete = true;
  for (int t = 0; t < 100; ++t) {
    in.now_us = t * hal::kMicrosPerSecond;
    CHECK_FALSE(nav.update(in).start_segment);
  }
}

TEST_GROUP(AbortMonitor){};

TEST(AbortMonitor, SameDepthStalledLeakAndLowBattery) {
  AbortLimits limits;
  limits.samedepth_for_s = 100.0;
  limits.stalled_for_s = 50.0;
  limits.remaining_charge_min_pct = 10.0;
  limits.battery_capacity_amphr = 100.0;
  AbortMonitor monitor(limits);
  AbortMonitorInputs in;
  in.phase = Phase::kDive;
  in.depth_ok = in.depth_rate_ok = in.leak_ok = in.power_ok = true;
  in.depth_m = 20.0;
  in.depth_rate_m_s = 0.2;
  in.gliding = true;
  // Moving: nothing.
  for (int t = 0; t < 200; ++t) {
    in.now_us = t * hal::kMicrosPerSecond;
    in.depth_m = 20.0 + 0.2 * t;
    CHECK(monitor.check(in) == AbortCause::kNone);
  }
  // Stalled (gliding the wrong way slowly) for longer than 50 s.
  in.depth_rate_m_s = 0.01;
  AbortCause cause = AbortCause::kNone;
  int t = 200;
  for (; t < 400 && cause == AbortCause::kNone; ++t) {
    in.now_us = t * hal::kMicrosPerSecond;
    in.depth_m += 0.01;
    cause = monitor.check(in);
  }
  CHECK(cause == AbortCause::kStalled);
  CHECK(t > 250 && t < 254);
  // The same depth (not gliding: the pump is moving) for longer than 100 s.
  AbortMonitor same(limits);
  in.gliding = false;
  cause = AbortCause::kNone;
  for (t = 0; t < 300 && cause == AbortCause::kNone; ++t) {
    in.now_us = t * hal::kMicrosPerSecond;
    in.depth_m = 30.0 + 0.3 * std::sin(0.1 * t);
    cause = same.check(in);
  }
  CHECK(cause == AbortCause::kSameDepth);
  CHECK(t > 100 && t < 104);
  AbortMonitor wet(limits);
  in.leak = true;
  CHECK(wet.check(in) == AbortCause::kLeak);
  in.leak = false;
  in.charge_used_amphr = 89.0;
  CHECK(AbortMonitor(limits).check(in) == AbortCause::kNone);
  in.charge_used_amphr = 91.0;
  CHECK(AbortMonitor(limits).check(in) == AbortCause::kLowBattery);
  in.power_ok = false;  // no valid reading: no verdict
  CHECK(AbortMonitor(limits).check(in) == AbortCause::kNone);
}
