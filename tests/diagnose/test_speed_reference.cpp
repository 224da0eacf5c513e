// SPDX-License-Identifier: Apache-2.0
// The validity check on a measured speed through water (speed_reference.hpp).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "glider/diagnose/speed_reference.hpp"

using namespace glider::diagnose;

TEST_GROUP(DiagnoseSpeedReference){};

TEST(DiagnoseSpeedReference, ImpliedWaterVelocityIsWhatTheSpeedLeavesOfTheDepthRate) {
  // A dive on a 24 deg glide path at 0.3 m/s in still water: the model's
  // depth rate is 0.3 sin 24 deg, and so is the measured one.
  const double path = 24.0 * M_PI / 180.0;
  const double w = 0.3 * std::sin(path);
  DOUBLES_EQUAL(0.0, implied_water_velocity(w, w, 0.3, 0.3), 1e-15);
  // A reference a third slow needs the water to sink the difference.
  DOUBLES_EQUAL(0.1 * std::sin(path), implied_water_velocity(w, w, 0.2, 0.3), 1e-15);
  // Climbs alike (rates negative): a slow reference needs rising water.
  DOUBLES_EQUAL(-0.1 * std::sin(path), implied_water_velocity(-w, -w, 0.2, 0.3), 1e-15);
  CHECK(std::isnan(implied_water_velocity(NAN, w, 0.3, 0.3)));
  CHECK(std::isnan(implied_water_velocity(w, w, 0.3, 0.0)));  // no glide path
}

TEST(DiagnoseSpeedReference, AYoFarFromTheOthersIsInconsistent) {
  std::vector<SpeedOfYo> by_yo(5);
  for (int k = 0; k < 5; ++k) by_yo[static_cast<std::size_t>(k)].yo = k;
  // yos 0, 2, 3: small implied velocities of both signs; yo 1: 4 cm/s; yo 4: none known.
  const std::vector<double> implied{0.004, -0.002, NAN, 0.041, 0.043, -0.001, 0.0};
  const std::vector<int> yo{0, 0, 4, 1, 1, 2, 3};
  DOUBLES_EQUAL(0.0005, check_reference_by_yo(by_yo, implied, yo, 0.02), 1e-15);  // median of 0.001, 0.042, -0.001, 0
  DOUBLES_EQUAL(0.001, by_yo[0].implied_water_w_m_s, 1e-15);
  CHECK_TRUE(by_yo[0].reference_consistent);
  DOUBLES_EQUAL(0.042, by_yo[1].implied_water_w_m_s, 1e-15);
  CHECK_FALSE(by_yo[1].reference_consistent);
  CHECK_TRUE(by_yo[2].reference_consistent);
  CHECK_TRUE(by_yo[3].reference_consistent);
  CHECK(std::isnan(by_yo[4].implied_water_w_m_s));
  CHECK_TRUE(by_yo[4].reference_consistent);  // unknown is not evidence against it
}

TEST(DiagnoseSpeedReference, AModelWrongForTheWholeLogBlamesNoYo) {
  // A wrong glide path shifts every yo's implied velocity alike (-67 mm/s
  // against WE01 on gliderflight-adcp): no reference is to blame but the odd one.
  std::vector<SpeedOfYo> by_yo(4);
  for (int k = 0; k < 4; ++k) by_yo[static_cast<std::size_t>(k)].yo = k;
  const std::vector<double> implied{-0.067, -0.065, -0.070, -0.001};
  const std::vector<int> yo{0, 1, 2, 3};
  DOUBLES_EQUAL(-0.066, check_reference_by_yo(by_yo, implied, yo, 0.02), 1e-15);
  for (int k = 0; k < 3; ++k) CHECK_TRUE(by_yo[static_cast<std::size_t>(k)].reference_consistent);
  CHECK_FALSE(by_yo[3].reference_consistent);
}
