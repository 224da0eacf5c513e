// SPDX-License-Identifier: Apache-2.0
// gliderflight's calibration carrying a stated vertical water velocity (the
// DVL protocol's --shared-water): on a log whose depth rate is the model's
// own flight plus a known water velocity, the calibration given that water
// finds the glider's C_D0 and m_g, and without it reads the water as a
// different glider. And the protocol's divergence verdict.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "glider/science/gliderflight_model.hpp"
#include "gliderflight_flown_log.hpp"

using namespace glider::science;

namespace {

constexpr double kWaterDown = -0.01;  // 1 cm/s up, as the DVL's near-zero-angle samples would need

GliderflightInput flown_in_water(const GliderflightParameters& truth) {
  return glider::science::test::flown_by(truth, kWaterDown);
}

}  // namespace

TEST_GROUP(GliderflightWater){};

TEST(GliderflightWater, StatedWaterVelocityLeavesTheGliderAsFlown) {
  GliderflightParameters truth;
  truth.cd0 = 0.16;
  truth.mass_kg = 69.95;
  GliderflightInput in = flown_in_water(truth);
  std::vector<bool> fit(in.time_s.size(), true);
  for (std::size_t i = 0; i < fit.size(); ++i) fit[i] = i % 300 >= 20 && i % 300 < 280;  // not the turns
  double rms_without = 0.0, rms_with = 0.0;
  const GliderflightParameters without = gliderflight_calibrate(GliderflightKind::kSteady, {}, in, fit, &rms_without);
  in.water_w_down_m_s.assign(in.time_s.size(), kWaterDown);
  const GliderflightParameters with = gliderflight_calibrate(GliderflightKind::kSteady, {}, in, fit, &rms_with);
  DOUBLES_EQUAL(truth.cd0, with.cd0, 0.002);
  DOUBLES_EQUAL(truth.mass_kg, with.mass_kg, 0.005);
  CHECK(rms_with < 1e-4);
  // Without the water the same depth rate is another glider (the water read as weight and drag) ...
  CHECK(std::abs(without.mass_kg - truth.mass_kg) > 0.02 || std::abs(without.cd0 - truth.cd0) > 0.01);
  CHECK(rms_without > 3.0 * rms_with);
  // ... and the speed through the water does not depend on the stated water.
  const GliderflightResult a = gliderflight_solve(GliderflightKind::kSteady, with, in);
  in.water_w_down_m_s.clear();
  const GliderflightResult b = gliderflight_solve(GliderflightKind::kSteady, with, in);
  for (std::size_t i = 0; i < a.speed_m_s.size(); i += 97) DOUBLES_EQUAL(a.speed_m_s[i], b.speed_m_s[i], 0.0);
}

TEST(GliderflightWater, WaterVelocityOutOfRangeRefused) {
  GliderflightParameters truth;
  GliderflightInput in = flown_in_water(truth);
  in.water_w_down_m_s.assign(in.time_s.size(), 0.0);
  in.water_w_down_m_s[5] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS(std::invalid_argument, gliderflight_solve(GliderflightKind::kSteady, truth, in));
  in.water_w_down_m_s.resize(3);
  CHECK_THROWS(std::invalid_argument, gliderflight_solve(GliderflightKind::kSteady, truth, in));
}

TEST(GliderflightWater, DivergedWhereMostFittedRecordsAreNotFinite) {
  GliderflightResult r;
  r.w_m_s = {0.1, std::nan(""), std::nan(""), 0.1, std::nan("")};
  CHECK_TRUE(gliderflight_diverged(r, {true, true, true, false, false}));   // 1 of 3 finite
  CHECK_FALSE(gliderflight_diverged(r, {true, true, false, true, false}));  // 2 of 3 finite
  CHECK_THROWS(std::invalid_argument, gliderflight_diverged(r, {true}));
}
