// SPDX-License-Identifier: Apache-2.0
// Health's rules on the fitting core and the base library: the pump rate's
// interval (serially correlated strokes), the UTC text. Synthetic, fast.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "glider/firmware/log/slocum_list.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/health/assess.hpp"
#include "glider/health/measure.hpp"

using namespace glider;

namespace {

// m_ballast_pumped every 4 s: `strokes` pump strokes (in and out by turns),
// each at its own rate drawn about `mean_cc_s` (a stroke's pressure and oil
// temperature set it), 12 samples each with 0.3 cc reading noise, the pump
// still for 3 samples between them.
flightlog::FlightLog strokes_log(std::mt19937& random, int strokes, double mean_cc_s, double stroke_sigma_cc_s) {
  std::normal_distribution<double> g(0.0, 1.0);
  std::string csv = "# source: health pump-rate test\nm_present_time,m_ballast_pumped\n";
  double t = 1000.0, v = -200.0;
  for (int s = 0; s < strokes; ++s) {
    const double rate = (mean_cc_s + stroke_sigma_cc_s * g(random)) * (s % 2 == 0 ? 1.0 : -1.0);
    for (int i = 0; i < 3; ++i, t += 4.0) csv += std::to_string(t) + "," + std::to_string(v + 0.3 * g(random)) + "\n";
    for (int i = 0; i < 12; ++i, t += 4.0) {
      v += rate * 4.0;
      csv += std::to_string(t) + "," + std::to_string(v + 0.3 * g(random)) + "\n";
    }
  }
  flightlog::ReadOptions only_the_pump;
  only_the_pump.required.clear();  // the raw file health reads the pump from (segments.cpp)
  return flightlog::parse_flight_log(csv, "strokes.csv", only_the_pump);
}

// `count` 8-hourly segments of 3 h with only a drag value each: value(k,
// day of the segment's middle), a +-`own_half` interval of its own and the
// shared shift `shift` (the Reynolds prior's: a bias every segment shares).
std::vector<health::SegmentMeasurement> drag_segments(int count, const std::function<double(int, double)>& value,
                                                      double own_half, double shift) {
  std::vector<health::SegmentMeasurement> segments;
  for (int k = 0; k < count; ++k) {
    health::SegmentMeasurement m;
    m.name = "seg" + std::to_string(k);
    m.start_s = k * 28800.0;
    m.end_s = m.start_s + 10800.0;
    m.time_s = 0.5 * (m.start_s + m.end_s);
    m.judged = true;
    const double v = value(k, m.time_s / 86400.0);
    for (health::EffectValue& e : m.effects) e = {std::nan(""), std::nan(""), std::nan(""), "not in this test"};
    m.effects[static_cast<std::size_t>(health::HealthEffect::kDragChange)] = {v, v - own_half, v + own_half, {}, shift};
    segments.push_back(m);
  }
  return segments;
}

// Fouling on 8-hourly segments: 12 at 1.0, then +3 % a day for 12 (4 days),
// each increment read at `gain` of the truth, with +-0.0001 of scatter and
// a +-`own_half` interval of its own.
std::vector<health::SegmentMeasurement> drag_ramp(double gain, double own_half) {
  std::mt19937 random(11u);
  std::normal_distribution<double> g(0.0, 1e-4);
  const double onset = 12 * 28800.0 / 86400.0;
  return drag_segments(
      24, [&](int, double day) { return 1.0 + gain * 0.03 * std::max(0.0, day - onset) + g(random); }, own_half, 0.0);
}

const health::Alert* drag_line_alert(const health::Assessment& a) {
  for (const health::Alert& alert : a.alerts) {
    if (alert.effect == health::HealthEffect::kDragChange && alert.kind == "line") return &alert;
  }
  return nullptr;
}

}  // namespace

TEST_GROUP(HealthRules){};

TEST(HealthRules, PumpRateIntervalCoversTheStrokesMean) {
  // Four strokes per segment whose rates differ by 3 cc/s (1 sigma): the
  // rates within a stroke are one stroke's, not independent samples. The
  // interval covers the strokes' mean in about 95 % of segments (Student-t
  // over the rates as independent covered 42 %).
  std::mt19937 random(2024u);
  int covered = 0;
  const int segments = 300;
  for (int k = 0; k < segments; ++k) {
    const health::EffectValue e = health::pump_rate(strokes_log(random, 4, 30.0, 3.0));
    CHECK_TRUE(e.judged());
    if (e.low <= 30.0 && 30.0 <= e.high) ++covered;
  }
  const double fraction = static_cast<double>(covered) / segments;
  UT_PRINT(("pump rate interval covered the strokes' mean in " + std::to_string(covered) + " of " +
            std::to_string(segments) + " segments")
               .c_str());
  CHECK_TEXT(fraction > 0.90 && fraction < 0.99, std::to_string(fraction).c_str());
}

TEST(HealthRules, PumpRateOfOneStrokeIsCountedOverItsEffectiveSamples) {
  // One stroke at a steady 30 cc/s: a value and a finite interval about it.
  std::mt19937 random(7u);
  const health::EffectValue e = health::pump_rate(strokes_log(random, 1, 30.0, 0.0));
  CHECK_TRUE(e.judged());
  DOUBLES_EQUAL(30.0, e.value, 0.2);
  CHECK(std::isfinite(e.low) && std::isfinite(e.high) && e.low < 30.0 && e.high > 30.0);
}

TEST(HealthRules, UtcTextIsTheBaseLibrarysAndRefusesANonFiniteTime) {
  // 2019-08-21T13:54:06.7Z: whole seconds, truncated; NaN has no text (the
  // gmtime path wrote -219246529-01-00T08:29:52Z).
  STRCMP_EQUAL("2019-08-21T13:54:06Z", health::utc_iso(1566395646.7).c_str());
  STRCMP_EQUAL("", health::utc_iso(std::nan("")).c_str());
}

TEST(HealthRules, AHingeRateIsKnownNoBetterThanItsSegmentsOwnIntervals) {
  // The ramp read with +-0.0001 of scatter but a +-0.004 interval of its
  // own (the plane's error, shared by every segment). The rate's interval is at least the two ends' own half-widths
  // over the line's days, hypot(0.004, 0.004) / 4 d = 0.0014 a day (4.7 % of the rate), where the scatter alone gave
  // +-0.0002.
  const std::vector<health::SegmentMeasurement> segments = drag_ramp(1.0, 0.004);
  const health::Assessment a = health::assess(segments);
  const health::Alert* line = drag_line_alert(a);
  CHECK(line != nullptr);
  DOUBLES_EQUAL(0.03, line->size, 0.002);
  const double span_days = (segments.back().time_s - segments[11].time_s) / 86400.0;
  const double floor = std::hypot(0.004, 0.004) / span_days;
  CHECK_TEXT(0.5 * (line->high - line->low) >= 0.99 * floor, line->message.c_str());
}

TEST(HealthRules, ADragLineIsNoLongerWidenedForTheDecimationGain) {
  // Until session 35 the vertical plane read a drag increment on the 4 s .sbd
  // at 0.986-0.997 of the truth and a drag line's interval reached out by
  // 1 / 0.986. The dynamic track now reads decimated depth, pitch and ballast
  // as stored (tests/decimation; docs/health.md, "Limits"): a +3 %/day ramp
  // read at gain 1 with tight own intervals (+-0.0005) keeps its statistical
  // interval, which covers the truth, and reaches no further (the rule
  // before: its high end at the reading over 0.986).
  const health::Assessment a = health::assess(drag_ramp(1.0, 0.0005));
  const health::Alert* line = drag_line_alert(a);
  CHECK(line != nullptr);
  DOUBLES_EQUAL(0.03, line->size, 0.0005);
  CHECK_TEXT(line->low <= 0.03 && 0.03 <= line->high, line->message.c_str());
  CHECK_TEXT(line->high < line->size / 0.986, line->message.c_str());
}

TEST(HealthRules, ALagIsNotKnownFinerThanHalfItsSampleSpacing) {
  // health.PumpLag's segments on 4 s .sbd: the core's interval +-0.12 s at
  // 28.7 s for a 30 s lag; at the SIL's lag-free pump [0, 0.006].
  const health::EffectValue after = health::lag_at_sampling_resolution({28.7, 28.58, 28.82, {}}, 4.0);
  DOUBLES_EQUAL(28.7, after.value, 1e-12);
  DOUBLES_EQUAL(26.7, after.low, 1e-12);
  DOUBLES_EQUAL(30.7, after.high, 1e-12);
  const health::EffectValue at_zero = health::lag_at_sampling_resolution({1e-7, 0.0, 0.006, {}}, 4.0);
  DOUBLES_EQUAL(0.0, at_zero.low, 1e-12);  // a lag has no sign
  DOUBLES_EQUAL(2.0 + 1e-7, at_zero.high, 1e-12);
  // Wider already: kept. Not judged, or no spacing: unchanged.
  const health::EffectValue wide = health::lag_at_sampling_resolution({10.0, 2.0, 18.0, {}}, 4.0);
  DOUBLES_EQUAL(2.0, wide.low, 1e-12);
  DOUBLES_EQUAL(18.0, wide.high, 1e-12);
  CHECK_FALSE(health::lag_at_sampling_resolution({std::nan(""), std::nan(""), std::nan(""), "why"}, 4.0).judged());
  DOUBLES_EQUAL(28.58, health::lag_at_sampling_resolution({28.7, 28.58, 28.82, {}}, std::nan("")).low, 1e-12);
}

TEST(HealthRules, DepthSampleSpacingIsTheMedianGapOfStoredDepths) {
  // Depth stored every 4 s with one 30 s gap and rows in between without it.
  std::string csv = "# source: health spacing test\nm_present_time,m_depth\n";
  double t = 0.0;
  for (int i = 0; i < 20; ++i, t += 4.0)
    csv += std::to_string(t) + "," + std::to_string(i) + "\n" + std::to_string(t + 1.0) + ",\n";
  csv += std::to_string(t + 26.0) + ",20\n";
  flightlog::ReadOptions only_depth;
  only_depth.required.clear();
  DOUBLES_EQUAL(4.0, health::depth_sample_spacing_s(flightlog::parse_flight_log(csv, "depth.csv", only_depth)), 1e-9);
}

namespace {

// `count` 8-hourly drag readings about `level` (+-0.003 of scatter, +-0.01
// own intervals), each with the shared shift `shift` (the Reynolds prior's:
// a bias every segment shares), a step of `step` after the first half.
std::vector<health::SegmentMeasurement> shared_bias_segments(int count, double level, double step, double shift) {
  std::mt19937 random(23u);
  std::normal_distribution<double> g(0.0, 0.003);
  return drag_segments(
      count, [&](int k, double) { return level + (k >= count / 2 ? step : 0.0) + g(random); }, 0.01, shift);
}

health::EffectAssessment drag_of(const health::Assessment& a) {
  return a.effects[static_cast<std::size_t>(health::HealthEffect::kDragChange)];
}

// The drag's assessment of the same segments without and with a shared shift.
std::pair<health::EffectAssessment, health::EffectAssessment> drag_without_and_with(double level, double step,
                                                                                    double shift) {
  return {drag_of(health::assess(shared_bias_segments(12, level, step, 0.0))),
          drag_of(health::assess(shared_bias_segments(12, level, step, shift)))};
}

}  // namespace

TEST(HealthRules, ALevelCarriesTheBiasEverySegmentShares) {
  // The Reynolds prior's shift is one exponent for the whole glider: every
  // segment shares it, and the level's interval from the segments' scatter
  // cannot hold it (it does not average down with more segments). The level
  // (a constant: its mean) widens to hypot(scatter's half-width, 1.96
  // |shift|); the shape and the value are the scatter's alone.
  const auto [a0, a1] = drag_without_and_with(1.37, 0.0, -0.015);
  CHECK(a0.trend.shape == glider::diagnose::TrendShape::kConstant);
  CHECK(a1.trend.shape == glider::diagnose::TrendShape::kConstant);
  DOUBLES_EQUAL(a0.value, a1.value, 0.0);
  const double scatter = 0.5 * (a0.high - a0.low);
  CHECK(scatter > 0.0 && scatter < 0.01);
  DOUBLES_EQUAL(std::hypot(scatter, 1.96 * 0.015), 0.5 * (a1.high - a1.low), 1e-9);
  DOUBLES_EQUAL(0.015, a1.trend.mean_shared.sigma, 1e-12);
  DOUBLES_EQUAL(0.015, a1.shared_sigma, 1e-12);
  // A change is a difference between segments, where the shared bias
  // cancels: a shift whose level interval alone is wider than the change that
  // matters (1.96 x 0.04 = 0.078 > the rule's 0.05) leaves the effect judged.
  const health::EffectAssessment a2 = drag_of(health::assess(shared_bias_segments(12, 1.37, 0.0, -0.04)));
  CHECK(0.5 * (a2.high - a2.low) > 0.05);
  CHECK_TEXT(a2.judged, a2.why.c_str());
}

TEST(HealthRules, AStepsLevelAfterCarriesTheSharedBiasButNotItsChange) {
  // A +10 % drag step half-way: the change is a difference between segments
  // (the shared bias cancels: the alert's interval is unchanged); the level
  // now (the mean after the step) carries it.
  const auto [a0, a1] = drag_without_and_with(1.0, 0.1, -0.02);
  CHECK(a1.trend.shape == glider::diagnose::TrendShape::kStep);
  CHECK_EQUAL(1U, a0.alerts.size());
  CHECK_EQUAL(1U, a1.alerts.size());
  DOUBLES_EQUAL(a0.alerts[0].low, a1.alerts[0].low, 0.0);
  DOUBLES_EQUAL(a0.alerts[0].high, a1.alerts[0].high, 0.0);
  DOUBLES_EQUAL(a0.value, a1.value, 0.0);
  DOUBLES_EQUAL(std::hypot(0.5 * (a0.high - a0.low), 1.96 * 0.02), 0.5 * (a1.high - a1.low), 1e-9);
}

// The fin's spread (health's turn measure, docs/health.md "The fin is judged
// only on segments that turn") counts only values under water (below 2 m) and
// is NaN with fewer than 10 of them - which the measurement then reads as
// "too thin to judge", never as evidence of turns.
TEST(HealthRules, FinSpreadCountsTheFinUnderWaterAndIsNaNWhenTooFew) {
  const double nan = std::nan("");
  const double rad = std::numbers::pi / 180.0;
  // 10 values under water alternating +-3 deg (sd 3.16 deg), one at the
  // surface at 20 deg and one not logged (stored on change): neither counts.
  flightlog::Column time, fin, depth;
  for (int i = 0; i < 12; ++i) {
    time.push_back(i * 4.0);
    fin.push_back(i == 10 ? 20.0 * rad : i == 11 ? nan : (i % 2 == 0 ? 3.0 : -3.0) * rad);
    depth.push_back(i == 10 ? 0.5 : 10.0);
  }
  const auto log_of = [&](const flightlog::Column& f) {
    return flightlog::FlightLog("spread.csv", {}, {"time", "m_fin", "m_depth"}, {time, f, depth}, 0);
  };
  DOUBLES_EQUAL(3.0 * std::sqrt(10.0 / 9.0), health::fin_spread_deg(log_of(fin)), 1e-9);
  flightlog::Column nine = fin;
  nine[0] = nan;  // 9 under water
  CHECK(std::isnan(health::fin_spread_deg(log_of(nine))));
}

// The heading's spread is circular (headings either side of north are close)
// and counts only headings under water; NaN with fewer than 10 of them.
TEST(HealthRules, HeadingSpreadIsCircularAndCountsTheHeadingUnderWater) {
  const double rad = std::numbers::pi / 180.0;
  flightlog::Column time, heading, depth;
  for (int i = 0; i < 12; ++i) {
    time.push_back(i * 4.0);
    // 10 under water at 357 and 3 deg; one at the surface at 180 deg; one not logged.
    heading.push_back(i == 10 ? 180.0 * rad : i == 11 ? std::nan("") : (i % 2 == 0 ? 357.0 : 3.0) * rad);
    depth.push_back(i == 10 ? 0.5 : 10.0);
  }
  const auto log_of = [&](const flightlog::Column& h) {
    return flightlog::FlightLog("heading.csv", {}, {"time", "m_heading", "m_depth"}, {time, h, depth}, 0);
  };
  // R = cos(3 deg): sqrt(-2 ln R) = 3.0011 deg.
  DOUBLES_EQUAL(std::sqrt(-2.0 * std::log(std::cos(3.0 * rad))) / rad, health::heading_spread_deg(log_of(heading)),
                1e-9);
  CHECK(health::heading_spread_deg(log_of(heading)) < 3.01);
  flightlog::Column nine = heading;
  nine[0] = std::nan("");
  CHECK(std::isnan(health::heading_spread_deg(log_of(nine))));
}

// bench_health --sbdlist tests/health/sbdlist_every_cycle.dat measures the
// decimation's part in a reading (docs/health.md, "The fin's bias in a
// random yaw"): the same sensors as the health tests' .sbd, every cycle.
TEST(HealthRules, TheEveryCycleSbdListIsTheHealthListWithoutDecimation) {
  const fw::SlocumListResult decimated = fw::read_slocum_list(GLIDER_SOURCE_DIR "/tests/health/sbdlist.dat");
  const fw::SlocumListResult every = fw::read_slocum_list(GLIDER_SOURCE_DIR "/tests/health/sbdlist_every_cycle.dat");
  CHECK_TEXT(decimated.error.empty(), decimated.error.c_str());
  CHECK_TEXT(every.error.empty(), every.error.c_str());
  CHECK(decimated.selection.logged == every.selection.logged);
  CHECK(std::any_of(decimated.selection.interval_s.begin(), decimated.selection.interval_s.end(),
                    [](double s) { return s > 0.0; }));
  for (double s : every.selection.interval_s) CHECK_EQUAL(0.0, s);
}
