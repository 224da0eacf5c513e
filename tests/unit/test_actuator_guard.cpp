// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>

#include "glider/firmware/actuator_guard.hpp"

using glider::fw::ActuatorGuard;

TEST_GROUP(ActuatorGuard){};

TEST(ActuatorGuard, CommandsInsideTheRangePassUnchangedAndUncounted) {
  ActuatorGuard guard({-250.0, 250.0, -1.0, 1.0, 0.45});
  DOUBLES_EQUAL(-250.0, guard.ballast_cc(-250.0), 0.0);
  DOUBLES_EQUAL(0.3, guard.battery_in(0.3), 0.0);
  DOUBLES_EQUAL(-0.45, guard.fin_rad(-0.45), 0.0);
  LONGS_EQUAL(0, guard.counts().total());
}

TEST(ActuatorGuard, OutsideTheRangeIsClampedAndCounted) {
  ActuatorGuard guard({-250.0, 250.0, -1.0, 1.0, 0.45});
  DOUBLES_EQUAL(-250.0, guard.ballast_cc(-1e308), 0.0);
  DOUBLES_EQUAL(250.0, guard.ballast_cc(1000.0), 0.0);
  DOUBLES_EQUAL(1.0, guard.battery_in(3.0), 0.0);
  DOUBLES_EQUAL(-0.45, guard.fin_rad(-2.0), 0.0);
  LONGS_EQUAL(2, guard.counts().ballast_clamped);
  LONGS_EQUAL(1, guard.counts().battery_clamped);
  LONGS_EQUAL(1, guard.counts().fin_clamped);
}

TEST(ActuatorGuard, NonFiniteCommandsBecomeTheSafeValue) {
  ActuatorGuard guard({-250.0, 250.0, -1.0, 0.5, 0.45});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  DOUBLES_EQUAL(250.0, guard.ballast_cc(nan), 0.0);   // full buoyancy: the glider rises
  DOUBLES_EQUAL(-0.25, guard.battery_in(-inf), 0.0);  // centre of the travel
  DOUBLES_EQUAL(0.0, guard.fin_rad(inf), 0.0);
  LONGS_EQUAL(3, guard.counts().non_finite);
}
