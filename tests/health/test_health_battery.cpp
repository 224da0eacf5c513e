// SPDX-License-Identifier: Apache-2.0
// Health's charge per km on a decimated file whose depth and pitch are
// stored in different cycles (each column on its own timer: after one
// skipped cycle they stay apart). Synthetic, fast.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/health/measure.hpp"

using namespace glider;

namespace {

constexpr double kPitchRad = 26.0 * std::numbers::pi / 180.0;
constexpr double kDepthRate = 0.2;  // m/s, diving
constexpr double kAmpHoursPerS = 1.0e-5;

// Dives from 5 m for `seconds`, one row a second; the depth stored every
// 4 s from t = 0, the pitch every 4 s from t = `pitch_phase_s`, the charge
// every 60 s. Empty (NaN): not stored in that row.
flightlog::FlightLog dive(int seconds, int pitch_phase_s) {
  const double nan = std::nan("");
  std::vector<double> time, charge, depth, pitch;
  for (int t = 0; t <= seconds; ++t) {
    time.push_back(t);
    charge.push_back(t % 60 == 0 ? kAmpHoursPerS * t : nan);
    depth.push_back(t % 4 == 0 ? 5.0 + kDepthRate * t : nan);
    // A pitch's store carries a little of the glide's wobble: a value that
    // changes, so the file stores it at every interval.
    pitch.push_back(t % 4 == pitch_phase_s ? -kPitchRad * (1.0 + 1e-4 * (t % 3)) : nan);
  }
  return flightlog::FlightLog("battery.csv", {}, {"m_present_time", "m_coulomb_amphr_total", "m_depth", "m_pitch"},
                              {time, charge, depth, pitch}, 0);
}

}  // namespace

TEST_GROUP(HealthBattery){};

// The distance is the depth's steps over tan(pitch): the pitch at a depth
// reading is its straight line between its own readings, so the phase of
// the two timers moves the value by the pitch's wobble only.
TEST(HealthBattery, DepthAndPitchStoredInDifferentCyclesReadTheSameChargePerKm) {
  const int seconds = 3600;
  const double distance_km = kDepthRate * seconds / std::tan(kPitchRad) / 1000.0;
  const double truth = kAmpHoursPerS * seconds / distance_km;
  const health::EffectValue aligned = health::battery_per_km(dive(seconds, 0));
  CHECK_TRUE(aligned.judged());
  DOUBLES_EQUAL(truth, aligned.value, 1e-3 * truth);
  for (int phase = 1; phase < 4; ++phase) {
    const health::EffectValue apart = health::battery_per_km(dive(seconds, phase));
    CHECK_TRUE(apart.judged());
    DOUBLES_EQUAL(truth, apart.value, 5e-3 * truth);  // the last depth step may have no pitch after it
  }
}
