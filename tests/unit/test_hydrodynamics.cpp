// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <numbers>

#include "glider/model/hydrodynamics.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

TEST_GROUP(Hydrodynamics) {
  Hydrodynamics h;
  void setup() override { h = load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml").hydro; }
};

TEST(Hydrodynamics, FitIsPaper000InsideItsRange) {
  for (double alpha : {-0.15, -0.05, 0.0, 0.03, 0.08, 0.17}) {
    const ForceCoefficients c = force_coefficients(h, alpha);
    DOUBLES_EQUAL(11.76 * alpha + 4.6 * alpha * std::abs(alpha), c.lift, 1e-12);
    DOUBLES_EQUAL(0.214 + 32.3 * alpha * alpha, c.drag, 1e-12);
    DOUBLES_EQUAL(-3.025 * alpha, moment_coefficient(h, alpha), 1e-12);
  }
}

TEST(Hydrodynamics, LiftIsOddDragIsEven) {
  for (double alpha = 0.0; alpha < std::numbers::pi; alpha += 0.01) {
    const ForceCoefficients up = force_coefficients(h, alpha);
    const ForceCoefficients down = force_coefficients(h, -alpha);
    DOUBLES_EQUAL(-up.lift, down.lift, 1e-12);
    DOUBLES_EQUAL(up.drag, down.drag, 1e-12);
    CHECK(up.drag > 0.0);
  }
}

TEST(Hydrodynamics, BroadsideIsCrossflow) {
  const ForceCoefficients c = force_coefficients(h, std::numbers::pi / 2.0);
  DOUBLES_EQUAL(0.0, c.lift, 1e-9);
  DOUBLES_EQUAL(h.crossflow_cn90, c.drag, 1e-9);
  DOUBLES_EQUAL(h.cm_alpha_m * std::sin(1.0) * std::cos(1.0), moment_coefficient(h, 1.0), 1e-12);
  DOUBLES_EQUAL(0.0, moment_coefficient(h, std::numbers::pi / 2.0), 1e-12);
}

TEST(Hydrodynamics, BlendIsContinuous) {
  // No jumps anywhere: the integrator would see them as impulses.
  const double step = 1e-5;
  for (double alpha = 0.0; alpha < 1.0; alpha += step) {
    const ForceCoefficients a = force_coefficients(h, alpha);
    const ForceCoefficients b = force_coefficients(h, alpha + step);
    CHECK(std::abs(a.lift - b.lift) < 1e-3);
    CHECK(std::abs(a.drag - b.drag) < 1e-3);
    CHECK(std::abs(moment_coefficient(h, alpha) - moment_coefficient(h, alpha + step)) < 1e-3);
  }
}
