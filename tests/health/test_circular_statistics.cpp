// SPDX-License-Identifier: Apache-2.0
// The circular statistics health's heading spread and the forecast's course
// straightness share (glider/circular_statistics): known spreads, north's
// wrap, weights, and the sums each tool wrote by hand before, bit for bit.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "glider/circular_statistics/circular_statistics.hpp"

namespace cs = glider::circular_statistics;

namespace {
constexpr double kRad = std::numbers::pi / 180.0;
}  // namespace

TEST_GROUP(CircularStatistics){};

TEST(CircularStatistics, OneAngleRepeatedHasLengthOneAndNoSpread) {
  cs::MeanResultant r;
  for (int i = 0; i < 5; ++i) r.add(242.0 * kRad);
  DOUBLES_EQUAL(1.0, r.length(), 1e-15);
  DOUBLES_EQUAL(5.0, r.total_weight(), 0.0);
  DOUBLES_EQUAL(0.0, cs::circular_sd_rad(r.length()), 1e-7);
}

TEST(CircularStatistics, TwoEqualLegsApartHaveLengthCosHalfTheAngle) {
  cs::MeanResultant r;
  r.add(242.0 * kRad, 1.9);
  r.add(305.0 * kRad, 1.9);
  DOUBLES_EQUAL(std::cos(31.5 * kRad), r.length(), 1e-15);
  // Weighted: a leg three times as long pulls the mean towards it; the length
  // is |3 e^{i0} + e^{i d}| / 4.
  cs::MeanResultant w;
  w.add(0.0, 3.0);
  w.add(90.0 * kRad, 1.0);
  DOUBLES_EQUAL(std::sqrt(10.0) / 4.0, w.length(), 1e-15);
}

TEST(CircularStatistics, HeadingsEitherSideOfNorthAreClose) {
  cs::MeanResultant across_north, across_south;
  for (double d : {-3.0, -1.0, 1.0, 3.0}) {
    across_north.add((360.0 + d) * kRad);
    across_south.add((180.0 + d) * kRad);
  }
  DOUBLES_EQUAL(across_south.length(), across_north.length(), 1e-15);
  // sd of +-1, +-3 deg is sqrt(5) deg; the circular sd agrees for so small a spread.
  DOUBLES_EQUAL(std::sqrt(5.0), cs::circular_sd_rad(across_north.length()) / kRad, 1e-3);
}

TEST(CircularStatistics, OppositeAnglesAndNoWeightAreTheEdges) {
  cs::MeanResultant opposite;
  opposite.add(0.0);
  opposite.add(std::numbers::pi);
  CHECK(opposite.length() < 1e-15);
  CHECK(std::isfinite(cs::circular_sd_rad(opposite.length())));
  CHECK(cs::circular_sd_rad(opposite.length()) > 5.0);  // R at rounding: sqrt(-2 ln 1e-16) = 8.6
  const cs::MeanResultant empty;
  CHECK(std::isnan(empty.length()));
  CHECK(std::isnan(cs::circular_sd_rad(std::nan(""))));
  cs::MeanResultant zero_weight;
  zero_weight.add(1.0, 0.0);
  CHECK(std::isnan(zero_weight.length()));
}

// The two hand-written sums this helper replaced (health's measure.cpp
// heading spread, the forecast's course_straightness), kept here as the
// reference: the helper must give the same bits, so neither tool's output moved.
TEST(CircularStatistics, BitIdenticalToTheSumsEachToolWroteByHand) {
  std::mt19937_64 random(20261128);
  std::uniform_real_distribution<double> angle(-4.0, 10.0), weight(0.0, 60.0);
  for (int trial = 0; trial < 200; ++trial) {
    cs::MeanResultant unweighted, weighted;
    double c = 0.0, s = 0.0, east = 0.0, north = 0.0, covered = 0.0;
    std::size_t n = 0;
    const int count = 10 + trial * 7;
    for (int i = 0; i < count; ++i) {
      const double a = trial % 2 == 0 ? angle(random) : 3.0 + 0.01 * angle(random);
      const double w = weight(random);
      c += std::cos(a);
      s += std::sin(a);
      ++n;
      unweighted.add(a);
      east += w * std::sin(a);
      north += w * std::cos(a);
      covered += w;
      weighted.add(a, w);
    }
    const double r = std::hypot(c, s) / static_cast<double>(n);
    const double spread = std::sqrt(-2.0 * std::log(std::clamp(r, 1e-300, 1.0)));
    CHECK_EQUAL(r, unweighted.length());
    CHECK_EQUAL(spread, cs::circular_sd_rad(unweighted.length()));
    CHECK_EQUAL(static_cast<double>(n), unweighted.total_weight());
    CHECK_EQUAL(std::hypot(east, north) / covered, weighted.length());
    CHECK_EQUAL(covered, weighted.total_weight());
  }
}
