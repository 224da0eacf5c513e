// SPDX-License-Identifier: Apache-2.0
// The breakdown of a speed error into parts (phase, depth, sign, size,
// angle of attack) on samples whose errors are known by construction.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "glider/science/speed_error_breakdown.hpp"

using glider::science::BreakdownRow;
using glider::science::ScoredSpeedSample;
using glider::science::speed_error_breakdown;

namespace {

constexpr double kPitch = -22.0 * M_PI / 180.0;
constexpr double kAlpha = 3.0 * M_PI / 180.0;

// Two dives of 300 s at 1 s, 12 -> 42 m, true speed 0.30 m/s on a path
// 3 deg steeper than the pitch. Model 0 is 1 cm/s fast, except 5 cm/s slow
// in the last 30 s of each dive; model 1 is exact. The depth rates are the
// measured speed's along the path (so the measured alpha is 3 deg).
std::vector<ScoredSpeedSample> two_dives() {
  std::vector<ScoredSpeedSample> out;
  for (int yo = 0; yo < 2; ++yo) {
    for (int k = 0; k < 300; ++k) {
      ScoredSpeedSample s;
      s.time_s = 1000.0 * yo + k;
      s.depth_m = 12.0 + 0.1 * k;
      s.yo = yo;
      s.measured_m_s = 0.30;
      s.model_m_s = {k >= 270 ? 0.25 : 0.31, 0.30};
      s.pitch_rad = kPitch;
      s.depth_rate_measured_m_s = 0.30 * std::sin(-kPitch + kAlpha);
      s.depth_rate_model_m_s = {s.model_m_s[0] * std::sin(-kPitch + kAlpha), s.depth_rate_measured_m_s};
      out.push_back(s);
    }
  }
  return out;
}

const BreakdownRow& row(const std::vector<BreakdownRow>& rows, const std::string& part) {
  for (const auto& r : rows) {
    if (r.part == part) return r;
  }
  FAIL(("no row " + part).c_str());
  throw std::logic_error("unreachable");
}

bool has_row(const std::vector<BreakdownRow>& rows, const std::string& part) {
  for (const auto& r : rows) {
    if (r.part == part) return true;
  }
  return false;
}

}  // namespace

TEST_GROUP(SpeedErrorBreakdown){};

TEST(SpeedErrorBreakdown, PartsOfAKnownError) {
  const auto samples = two_dives();
  const auto rows = speed_error_breakdown(samples, std::vector<bool>(samples.size(), true));
  // Total: 540 samples at +1 cm/s, 60 at -5 cm/s.
  const double total_sq = 540 * 1e-4 + 60 * 25e-4;
  const BreakdownRow& all = row(rows, "all");
  UNSIGNED_LONGS_EQUAL(600, all.samples[0]);
  DOUBLES_EQUAL(std::sqrt(total_sq / 600), all.rms_m_s[0], 1e-12);
  DOUBLES_EQUAL(0.0, all.rms_m_s[1], 1e-12);
  DOUBLES_EQUAL(1.0, all.share[0], 1e-12);
  // The last 60 s before each dive's end: 30 s at +1, 30 s at -5 cm/s.
  const BreakdownRow& approach = row(rows, "phase: approaching an inflection");
  UNSIGNED_LONGS_EQUAL(120, approach.samples[0]);
  DOUBLES_EQUAL((60 * 1e-4 + 60 * 25e-4) / total_sq, approach.share[0], 1e-12);
  DOUBLES_EQUAL(-0.02, approach.mean_m_s[0], 1e-12);
  // 12-15 m near the surface (30 samples a dive), the next 30 s leaving the top.
  UNSIGNED_LONGS_EQUAL(60, row(rows, "phase: near-surface").samples[0]);
  UNSIGNED_LONGS_EQUAL(60, row(rows, "phase: leaving an inflection").samples[0]);
  UNSIGNED_LONGS_EQUAL(600 - 60 - 60 - 120, row(rows, "phase: steady dive").samples[0]);
  CHECK_FALSE(has_row(rows, "phase: steady climb"));  // no climb: no row
  // Sign and size split each model's own samples.
  const BreakdownRow& slow = row(rows, "sign: model slow");
  UNSIGNED_LONGS_EQUAL(60, slow.samples[0]);
  UNSIGNED_LONGS_EQUAL(600, slow.samples[1]);  // an error of 0 counts as slow
  DOUBLES_EQUAL(60 * 25e-4 / total_sq, slow.share[0], 1e-12);
  UNSIGNED_LONGS_EQUAL(60, row(rows, "size: error beyond 3 cm/s").samples[0]);
  UNSIGNED_LONGS_EQUAL(540, row(rows, "size: error 1-3 cm/s either way").samples[0]);
  // Depth bins of 10 m: 10-20 m holds 12.0-19.9 m (80 samples a dive).
  UNSIGNED_LONGS_EQUAL(160, row(rows, "depth 10-20 m").samples[0]);
  // The angle of attack: 3 deg measured and for both models (each flies along its own path).
  const BreakdownRow& a = row(rows, "measured alpha 3-4 deg");
  UNSIGNED_LONGS_EQUAL(0, row(rows, "all").samples[0] - a.samples[0]);  // every sample in that bin
  DOUBLES_EQUAL(3.0, a.alpha_measured_deg, 1e-9);
  DOUBLES_EQUAL(3.0, a.alpha_model_deg[0], 1e-9);
}

TEST(SpeedErrorBreakdown, YoMeansRemovedLeavesTheWithinYoStructure) {
  auto samples = two_dives();
  for (auto& s : samples) s.model_m_s[1] = s.measured_m_s + (s.yo == 0 ? 0.02 : -0.01);  // a constant per yo
  const auto rows = speed_error_breakdown(samples, std::vector<bool>(samples.size(), true));
  DOUBLES_EQUAL(std::sqrt((4e-4 + 1e-4) / 2), row(rows, "all").rms_m_s[1], 1e-12);
  DOUBLES_EQUAL(0.0, row(rows, "yo means removed").rms_m_s[1], 1e-12);
  CHECK(row(rows, "yo means removed").rms_m_s[0] > 0.01);  // model 0's error is within its yos
}

TEST(SpeedErrorBreakdown, ImpliedAngleOfAttack) {
  DOUBLES_EQUAL(3.0, glider::science::implied_alpha_deg(0.3, -0.3 * std::sin(-kPitch + kAlpha), -kPitch), 1e-9);
  CHECK(std::isnan(glider::science::implied_alpha_deg(0.1, 0.2, kPitch)));  // no path climbs faster than it flies
  CHECK(std::isnan(glider::science::implied_alpha_deg(0.0, 0.0, kPitch)));
  CHECK(std::isnan(glider::science::implied_alpha_deg(std::nan(""), 0.1, kPitch)));
}

TEST(SpeedErrorBreakdown, OnlyUsedFiniteSamplesCount) {
  auto samples = two_dives();
  std::vector<bool> use(samples.size(), true);
  for (std::size_t i = 0; i < 300; ++i) use[i] = false;                  // yo 0 left out
  samples[400].measured_m_s = std::numeric_limits<double>::quiet_NaN();  // NaN never counts
  const auto rows = speed_error_breakdown(samples, use);
  UNSIGNED_LONGS_EQUAL(299, row(rows, "all").samples[0]);
  CHECK_THROWS(std::invalid_argument, speed_error_breakdown(samples, std::vector<bool>(3, true)));
  CHECK(speed_error_breakdown(samples, std::vector<bool>(samples.size(), false)).empty());
}
