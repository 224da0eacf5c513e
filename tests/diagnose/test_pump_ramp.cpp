// SPDX-License-Identifier: Apache-2.0
// The pump between a thinned log's samples (pump_ramp.hpp): a stroke sampled
// every 2-5 s is rebuilt as the hold-ramp-hold the pump flew, and the lag of
// the displaced volume is advanced exactly along it.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstddef>
#include <vector>

#include "glider/diagnose/pump_ramp.hpp"
#include "glider/model/first_order_lag.hpp"

using namespace glider;

namespace {

// A pump holding +250 cc, emptying at 30 cc/s from t = 101.3 s to -250 cc
// (16.7 s), then holding: the truth a log samples.
double pumped_cc(double t) {
  constexpr double kStart = 101.3, kRate = 30.0;
  if (t <= kStart) return 250.0;
  return std::max(-250.0, 250.0 - kRate * (t - kStart));
}

struct Sampled {
  std::vector<double> time, cc;
};

Sampled sample(const std::vector<double>& times) {
  Sampled s{times, {}};
  for (double t : times) s.cc.push_back(pumped_cc(t));
  return s;
}

// The ballast rebuilt at time t from the samples and their ramps.
double rebuilt(const Sampled& s, const std::vector<diagnose::PumpRamp>& ramps, double t) {
  std::size_t i = 0;
  while (i + 2 < s.time.size() && s.time[i + 1] < t) ++i;
  const double f = (t - s.time[i]) / (s.time[i + 1] - s.time[i]);
  return diagnose::ramp_value(s.cc[i], s.cc[i + 1], ramps[i], f);
}

// Rows 2-5 s apart across the stroke, like a thinned Slocum log.
const std::vector<double> kThinned{90.0, 93.0, 97.5, 100.0, 103.0, 107.5, 110.0, 113.5, 118.0, 121.0, 124.5, 128.0};

}  // namespace

TEST_GROUP(DiagnosePumpRamp){};

TEST(DiagnosePumpRamp, ThinnedStrokeIsTheHoldRampHoldThePumpFlew) {
  const Sampled s = sample(kThinned);
  const std::vector<std::size_t> run_first{0};
  const std::vector<diagnose::PumpRamp> ramps = diagnose::pump_ramps(s.time, s.cc, run_first);
  double worst = 0.0, worst_line = 0.0;
  for (double t = kThinned.front(); t <= kThinned.back(); t += 0.05) {
    worst = std::max(worst, std::abs(rebuilt(s, ramps, t) - pumped_cc(t)));
    const std::vector<diagnose::PumpRamp> lines(s.time.size());
    worst_line = std::max(worst_line, std::abs(rebuilt(s, lines, t) - pumped_cc(t)));
  }
  DOUBLES_EQUAL(0.0, worst, 1e-9);  // the inner intervals give the rate, the ends the start and stop
  CHECK(worst_line > 20.0);         // a straight line between samples starts 1.3 s early: 22 cc off
}

TEST(DiagnosePumpRamp, JitterAndStrokesWithoutInnerIntervalsStayLines) {
  // Holding with the sensor's sub-cc jitter, then one stroke inside one
  // interval, in a log with no inner interval anywhere: the rate is unknown.
  const std::vector<double> time{0.0, 4.0, 8.0, 12.0, 16.0};
  const std::vector<double> cc{250.0, 249.7, 250.2, -250.0, -250.0};
  const std::vector<std::size_t> run_first{0};
  for (const diagnose::PumpRamp& r : diagnose::pump_ramps(time, cc, run_first)) {
    DOUBLES_EQUAL(0.0, r.start, 0.0);
    DOUBLES_EQUAL(1.0, r.end, 0.0);
  }
}

TEST(DiagnosePumpRamp, StrokesDoNotCrossRuns) {
  // The same samples cut into two runs inside the stroke (107.5 s | 110 s):
  // each run holds two moving intervals, none inner, so the rate is unknown
  // and every ramp stays a line. Joined, the intervals about the cut would be
  // inner ones and set the rate (the test above).
  const Sampled s = sample(kThinned);
  const std::vector<std::size_t> run_first{0, 6};
  for (const diagnose::PumpRamp& r : diagnose::pump_ramps(s.time, s.cc, run_first)) {
    DOUBLES_EQUAL(0.0, r.start, 0.0);
    DOUBLES_EQUAL(1.0, r.end, 0.0);
  }
}

TEST(DiagnosePumpRamp, LagIsAdvancedExactlyAlongTheRamp) {
  // A 7 s lag of the rebuilt stroke, advanced in one call per interval, against
  // the same lag advanced in 1 ms steps of the true pumped volume.
  const Sampled s = sample(kThinned);
  const std::vector<std::size_t> run_first{0};
  const std::vector<diagnose::PumpRamp> ramps = diagnose::pump_ramps(s.time, s.cc, run_first);
  constexpr double kLag = 7.0;
  double lagged = s.cc.front(), fine = s.cc.front();
  for (std::size_t i = 0; i + 1 < s.time.size(); ++i) {
    const double dt = s.time[i + 1] - s.time[i];
    // Two calls: from the start to 0.4 and on to the end (the model's RK4 stages).
    const double mid = diagnose::lag_over_ramp(lagged, s.cc[i], s.cc[i + 1], ramps[i], 0.0, 0.4, dt, kLag);
    lagged = diagnose::lag_over_ramp(mid, s.cc[i], s.cc[i + 1], ramps[i], 0.4, 1.0, dt, kLag);
    const int steps = static_cast<int>(std::lround(dt / 1e-3));
    for (int k = 0; k < steps; ++k) {
      const double t0 = s.time[i] + k * dt / steps, t1 = s.time[i] + (k + 1) * dt / steps;
      fine = model::first_order_lag_after(fine, pumped_cc(t0), pumped_cc(t1), t1 - t0, kLag);
    }
    DOUBLES_EQUAL(fine, lagged, 1e-6);
  }
  // Without a lag the displaced volume is the ramp itself.
  DOUBLES_EQUAL(pumped_cc(104.0), diagnose::lag_over_ramp(0.0, s.cc[4], s.cc[5], ramps[4], 0.0, 1.0 / 4.5, 4.5, 0.0),
                1e-9);
}
