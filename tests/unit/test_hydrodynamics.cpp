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

// The identified shallow Slocum's wings are gliderflight's (Merckelbach et
// al. 2019): AR 7, 43 deg sweep, Oswald 0.8 on S = 0.1 m^2 give a lift
// slope of 3.734 /rad and an induced drag of 0.793 /rad^2, which with the
// hull's 3.8 and 9.7 are gliderflight's aw + ah and its Cd1 of 10.5.
TEST(Hydrodynamics, WingsFromThePlanform) {
  const Hydrodynamics s = load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml").hydro;
  DOUBLES_EQUAL(3.7343, wing_lift_slope_per_rad(s), 1e-4);
  DOUBLES_EQUAL(0.7926, wing_induced_drag_per_rad2(s), 1e-4);
  DOUBLES_EQUAL(10.5, s.cd_alpha2 + wing_induced_drag_per_rad2(s), 0.02);
  for (double alpha : {-0.1, -0.02, 0.0, 0.05, 0.15}) {
    const ForceCoefficients c = force_coefficients(s, alpha);
    DOUBLES_EQUAL((3.8 + wing_lift_slope_per_rad(s)) * alpha, c.lift, 1e-12);
    DOUBLES_EQUAL(s.cd0 + (9.7 + wing_induced_drag_per_rad2(s)) * alpha * alpha, c.drag, 1e-12);
  }
  // Half the wing area referred to the same area: half the wings' share.
  Hydrodynamics half = s;
  half.wing_area_m2 = 0.05;
  DOUBLES_EQUAL(0.5 * wing_lift_slope_per_rad(s), wing_lift_slope_per_rad(half), 1e-12);
  DOUBLES_EQUAL(0.5 * wing_induced_drag_per_rad2(s), wing_induced_drag_per_rad2(half), 1e-12);
  // Without wings nothing is added (WE01: the paper's polynomial alone).
  DOUBLES_EQUAL(0.0, wing_lift_slope_per_rad(h), 0.0);
  DOUBLES_EQUAL(h.cl_alpha, lift_slope_per_rad(h), 0.0);
}
