// SPDX-License-Identifier: Apache-2.0
// The shapes of an effect over a deployment (constant, linear, step, hinge) on
// seeded synthetic series: each found where it is, and spurious shapes in
// pure noise no more often than the significance level allows.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <random>
#include <vector>

#include "glider/diagnose/trend.hpp"

using glider::diagnose::fit_trend;
using glider::diagnose::Trend;
using glider::diagnose::TrendShape;

namespace {

constexpr double kDay = 86400.0;

// Normal draws from the top bits (Box-Muller): the same on every platform.
double normal(std::mt19937_64& rng) {
  const double u1 = (static_cast<double>(rng() >> 11) + 0.5) / 9007199254740992.0;
  const double u2 = static_cast<double>(rng() >> 11) / 9007199254740992.0;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * 3.141592653589793 * u2);
}

std::vector<double> days(std::size_t n) {
  std::vector<double> t;
  for (std::size_t i = 0; i < n; ++i) t.push_back(1.7e9 + (static_cast<double>(i) + 0.1 * (i % 3)) * kDay);
  return t;
}

}  // namespace

TEST_GROUP(DiagnoseTrend) { std::mt19937_64 rng{20261125}; };

TEST(DiagnoseTrend, LinearGrowthIsALineWithItsRate) {
  const std::vector<double> t = days(14);
  std::vector<double> y;
  for (double ti : t) y.push_back(1.10 + 0.03 * (ti - t.front()) / kDay + 0.01 * normal(rng));
  const Trend trend = fit_trend(t, y);
  STRCMP_EQUAL("linear", to_string(trend.shape));
  CHECK(trend.slope_per_day.low < 0.03 && 0.03 < trend.slope_per_day.high);
  DOUBLES_EQUAL(0.03, trend.slope_per_day.value, 0.005);
  DOUBLES_EQUAL(1.10 + 0.03 * 13.2, trend.at(t.back()), 0.03);
}

TEST(DiagnoseTrend, OneStepIsAStepBetweenTheRightSegments) {
  const std::vector<double> t = days(12);
  std::vector<double> y;
  for (std::size_t i = 0; i < t.size(); ++i) y.push_back((i < 7 ? -5.0 : -48.0) + 3.0 * normal(rng));
  const Trend trend = fit_trend(t, y);
  STRCMP_EQUAL("step", to_string(trend.shape));
  DOUBLES_EQUAL(t[6], trend.step_before_s, 1.0);
  DOUBLES_EQUAL(t[7], trend.step_after_s, 1.0);
  CHECK(trend.step_change.low < -43.0 && -43.0 < trend.step_change.high);
}

TEST(DiagnoseTrend, FoulingFromSomeDayOnIsAHingeWithItsOnsetAndRate) {
  // A surfacing every 8 h, constant for 4 days, then +3 % a day for 2 days:
  // the constant stretch pins the level, the line after it is the rate.
  std::vector<double> t, y;
  for (std::size_t i = 0; i < 18; ++i) {
    t.push_back(1.7e9 + static_cast<double>(i) * kDay / 3.0);
    const double days_fouled = std::max(0.0, (t.back() - t.front()) / kDay - 4.0);
    y.push_back(1.0 + 0.03 * days_fouled + 0.004 * normal(rng));
  }
  const Trend trend = fit_trend(t, y);
  STRCMP_EQUAL("hinge", to_string(trend.shape));
  CHECK(trend.p_hinge < 0.05 / 3.0);
  CHECK(trend.bic_hinge < trend.bic_linear && trend.bic_hinge < trend.bic_step);
  DOUBLES_EQUAL(t.front() + 4.0 * kDay, trend.hinge_s, kDay / 3.0 + 1.0);
  CHECK(trend.hinge_slope_per_day.low < 0.03 && 0.03 < trend.hinge_slope_per_day.high);
  const double now = 1.0 + 0.03 * (17.0 / 3.0 - 4.0);
  CHECK(trend.hinge_end.low < now && now < trend.hinge_end.high);
  DOUBLES_EQUAL(trend.hinge_level.value, trend.at(t.front()), 1e-12);
  DOUBLES_EQUAL(trend.hinge_end.value, trend.at(t.back()), 1e-12);
}

TEST(DiagnoseTrend, NoiseIsConstantAtTheSignificanceLevel) {
  // 400 series of pure noise: a spurious line, step or hinge in at most about
  // 5 % of them (each shape tested at a third of the level).
  int spurious = 0;
  for (int series = 0; series < 400; ++series) {
    const std::vector<double> t = days(10);
    std::vector<double> y;
    for (std::size_t i = 0; i < t.size(); ++i) y.push_back(2.0 + normal(rng));
    const Trend trend = fit_trend(t, y);
    CHECK(trend.shape != TrendShape::kNone);
    if (trend.shape != TrendShape::kConstant) ++spurious;
  }
  UT_PRINT(("spurious shapes in 400 noise series: " + std::to_string(spurious)).c_str());
  CHECK(spurious <= 30);
  CHECK(spurious >= 4);  // a test that never sees a false alarm is not testing the level
}

TEST(DiagnoseTrend, MissingValuesAreLeftOutAndTooFewGiveNone) {
  const std::vector<double> t = days(4);
  const double nan = std::nan("");
  const std::vector<double> y{1.0, nan, 1.1, nan};
  const Trend trend = fit_trend(t, y);
  STRCMP_EQUAL("none", to_string(trend.shape));
  LONGS_EQUAL(2, trend.segments);
  CHECK(std::isnan(trend.at(t[0])));
}
