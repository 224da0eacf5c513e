// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include "glider/firmware/pi_controller.hpp"

using glider::fw::PiController;
using glider::fw::PiGains;

TEST_GROUP(PiController) { PiGains gains{2.0, 0.5, -1.0, 1.0}; };

TEST(PiController, ProportionalPlusIntegral) {
  PiController pi(gains);
  pi.reset(0.0);
  // kp e + ki e dt = 2 * 0.1 + 0.5 * 0.1 * 1
  DOUBLES_EQUAL(0.25, pi.update(0.1, 1.0), 1e-12);
  DOUBLES_EQUAL(0.05, pi.integrator(), 1e-12);
  DOUBLES_EQUAL(0.30, pi.update(0.1, 1.0), 1e-12);
  CHECK_FALSE(pi.saturated());
}

TEST(PiController, BumplessReset) {
  PiController pi(gains);
  pi.reset(0.4);
  DOUBLES_EQUAL(0.4, pi.output(), 1e-12);
  DOUBLES_EQUAL(0.4, pi.update(0.0, 1.0), 1e-12);
  pi.reset(5.0);  // outside the limits: clamped
  DOUBLES_EQUAL(1.0, pi.output(), 1e-12);
}

TEST(PiController, OutputSaturates) {
  PiController pi(gains);
  pi.reset(0.0);
  DOUBLES_EQUAL(1.0, pi.update(2.0, 0.1), 1e-12);
  CHECK_TRUE(pi.saturated());
  DOUBLES_EQUAL(-1.0, pi.update(-3.0, 0.1), 1e-12);
  CHECK_TRUE(pi.saturated());
}

TEST(PiController, IntegratorDoesNotWindUpWhileSaturated) {
  PiController pi(gains);
  pi.reset(0.9);
  for (int i = 0; i < 1000; ++i) pi.update(0.2, 1.0);  // pushes against +1 for 1000 s
  CHECK_TRUE(pi.saturated());
  CHECK(pi.integrator() <= 1.0);
  // The error reverses: the output must leave the limit at once, not after
  // unwinding 1000 s of accumulated integral.
  const double out = pi.update(-0.2, 1.0);
  CHECK(out < 1.0);
  DOUBLES_EQUAL(pi.integrator() - 0.4, out, 1e-12);
}

TEST(PiController, IntegratorFrozenOnlyInTheSaturatingDirection) {
  PiController low(gains);
  low.reset(-0.8);
  low.update(-1.0, 1.0);  // saturated at -1 by the P term: integral frozen
  CHECK_TRUE(low.saturated());
  const double frozen = low.integrator();
  DOUBLES_EQUAL(-0.8, frozen, 1e-12);
  low.update(-0.6, 1.0);  // would push further below: still frozen
  DOUBLES_EQUAL(frozen, low.integrator(), 1e-12);
  low.update(0.1, 1.0);  // back toward the inside: integrates at once
  DOUBLES_EQUAL(frozen + 0.05, low.integrator(), 1e-12);
}
