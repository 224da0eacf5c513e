// SPDX-License-Identifier: Apache-2.0
// Slocum's goto current correction (firmware current_correction.hpp) on
// hand-computed cases, and its guards.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "glider/firmware/current_correction.hpp"

using namespace glider::fw;

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

TEST_GROUP(CurrentCorrection){};

TEST(CurrentCorrection, StillWaterSteersTheBearing) {
  DOUBLES_EQUAL(std::numbers::pi / 4.0, aim_point_heading({0.0, 0.0}, {1000.0, 1000.0}, {0.0, 0.0}, 0.3), 1e-12);
}

TEST(CurrentCorrection, AimsAtTheWaypointMovedUpstreamByCurrentTimesTimeToGo) {
  // 10 km north at 0.3 m/s: 33 333 s to go; 0.1 m/s east moves the aim
  // 3333 m west: atan(1/3) west of north (the crab law said asin(1/3)).
  DOUBLES_EQUAL(kTwoPi - std::atan(1.0 / 3.0), aim_point_heading({0.0, 0.0}, {0.0, 10000.0}, {0.1, 0.0}, 0.3), 1e-12);
  // The same from a DR position that is not the origin: only the offset counts.
  DOUBLES_EQUAL(kTwoPi - std::atan(1.0 / 3.0), aim_point_heading({500.0, -200.0}, {500.0, 9800.0}, {0.1, 0.0}, 0.3),
                1e-12);
}

TEST(CurrentCorrection, ACurrentStrongerThanTheGliderStillSteersTowardsTheWaypoint) {
  // Comet-2019's case: 0.48 m/s east against 0.27 m/s, the waypoint 1 km
  // east and 1 km north. Time to go 1414.2 / 0.27 = 5237.8 s; the aim point
  // 2514.2 m west of the waypoint: (-1514.2, 1000), heading 303.44 deg,
  // still north of west (towards the waypoint's northing). The capped crab
  // law said 45 - 60 = 345 deg.
  const double heading = aim_point_heading({0.0, 0.0}, {1000.0, 1000.0}, {0.48, 0.0}, 0.27);
  DOUBLES_EQUAL(5.296063753378703, heading, 1e-9);
  CHECK(std::cos(heading) > 0.0);
}

TEST(CurrentCorrection, ACurrentAlongTheTrackMovesTheAimAlongTheTrack) {
  // A head current, even twice the glider's speed: the aim goes further
  // out on the same line, the heading stays on the waypoint.
  DOUBLES_EQUAL(0.0, aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.0, -0.5}, 0.27), 1e-12);
  // A following current faster than the glider puts the aim point behind it
  // (1000 - 0.5 * 3704 = -852 m): Slocum's law then heads into the current
  // and lets it carry the glider to the waypoint at 0.5 - 0.27 m/s. Kept as
  // Slocum flies it (docs/missions.md says so).
  DOUBLES_EQUAL(std::numbers::pi, aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.0, 0.5}, 0.27), 1e-12);
  // Slower than the glider: the aim stays ahead (1000 - 0.2 * 3704 = 259 m).
  DOUBLES_EQUAL(0.0, aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.0, 0.2}, 0.27), 1e-12);
}

TEST(CurrentCorrection, ASlowAverageCountsAsTheFloorSpeed) {
  // 1000 m at 0.1 m/s (the floor, not 0.02): 10 000 s; 0.01 m/s east: 100 m.
  DOUBLES_EQUAL(kTwoPi - std::atan(0.1), aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.01, 0.0}, 0.02), 1e-12);
  DOUBLES_EQUAL(0.1, kMinAimSpeedMps, 0.0);
}

TEST(CurrentCorrection, NoAnswerFromBadInputOrNoWayToGo) {
  CHECK(std::isnan(aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.1, 0.0}, 0.0)));
  CHECK(std::isnan(aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.1, 0.0}, -0.3)));
  CHECK(std::isnan(aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {0.1, 0.0}, kNaN)));
  CHECK(std::isnan(aim_point_heading({kNaN, 0.0}, {0.0, 1000.0}, {0.1, 0.0}, 0.3)));
  CHECK(std::isnan(aim_point_heading({0.0, 0.0}, {0.0, INFINITY}, {0.1, 0.0}, 0.3)));
  CHECK(std::isnan(aim_point_heading({0.0, 0.0}, {0.0, 1000.0}, {kNaN, 0.0}, 0.3)));
  // On the waypoint: nothing to aim at (the navigator keeps its bearing).
  CHECK(std::isnan(aim_point_heading({10.0, 20.0}, {10.0, 20.0}, {0.1, 0.0}, 0.3)));
}
