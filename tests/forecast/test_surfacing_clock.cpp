// SPDX-License-Identifier: Apache-2.0
// The surfacing clock's seed (docs/forecast.md "The surfacing clock"): how
// long before the last arrival the periodic when_secs clock fired, from the
// chain of arrivals. Synthetic histories whose climbs left (tau) are known.
#include <CppUTest/TestHarness.h>

#include <vector>

#include "glider/forecast/forecast.hpp"

namespace fc = glider::forecast;

namespace {

constexpr double kWhenSecs = 10800.0;
constexpr double kUp = 600.0;  // at the surface each time

glider::fw::MissionPlan plan() {
  glider::fw::MissionPlan p;
  p.surface_interval_s = kWhenSecs;
  return p;
}

// Arrivals of a glider whose clock started at t = 0 and fired every when_secs,
// each arrival tau_k after its firing; the first event is the launch at 0
// (mission time 0) unless `launch` is false, the others at mission time >= when_secs
// (-1: not said, as a shore without MT: lines).
std::vector<fc::Surfacing> history(const std::vector<double>& taus, bool launch, bool say_mission_time) {
  std::vector<fc::Surfacing> h;
  if (launch) {
    fc::Surfacing s;
    s.call_start_utc_s = 0.0;
    s.call_end_utc_s = kUp;
    s.mission_time_s = say_mission_time ? 0.0 : -1.0;
    h.push_back(s);
  }
  for (std::size_t k = 0; k < taus.size(); ++k) {
    fc::Surfacing s;
    s.call_start_utc_s = kWhenSecs * static_cast<double>(k + 1) + taus[k];
    s.call_end_utc_s = s.call_start_utc_s + kUp;
    s.mission_time_s = say_mission_time ? s.call_start_utc_s : -1.0;
    h.push_back(s);
  }
  return h;
}

}  // namespace

TEST_GROUP(ForecastSurfacingClock){};

// The launch anchors the chain: the clock started with the mission, so every
// later tau is known exactly (the SIL truths' case).
TEST(ForecastSurfacingClock, TheLaunchAnchorsTheChain) {
  const std::vector<double> taus = {300.0, 16.0, 287.0, 33.0};
  const std::vector<fc::Surfacing> h = history(taus, true, true);
  DOUBLES_EQUAL(33.0, fc::climb_left_at_firing_s(h, h.size() - 1, plan(), 400.0), 1e-9);
  DOUBLES_EQUAL(287.0, fc::climb_left_at_firing_s(h, h.size() - 2, plan(), 400.0), 1e-9);
  // The launch itself: the clock started then (its mission time).
  DOUBLES_EQUAL(0.0, fc::climb_left_at_firing_s(h, 0, plan(), 400.0), 1e-9);
}

// Without an anchor each tau is known up to one constant, bounded by
// [0, longest] for every tau of the chain: the middle of what is left.
TEST(ForecastSurfacingClock, WithoutAnAnchorTheMiddleOfWhatTheChainAllows) {
  const std::vector<double> taus = {120.0, 30.0, 200.0};
  const std::vector<fc::Surfacing> h = history(taus, false, false);
  // tau_last = y; the others y - 80 and y - 170: y in [170, 300]: 235.
  DOUBLES_EQUAL(235.0, fc::climb_left_at_firing_s(h, h.size() - 1, plan(), 300.0), 1e-9);
  // One surfacing: half the longest climb (the mean over the yo).
  const std::vector<fc::Surfacing> one(h.begin(), h.begin() + 1);
  DOUBLES_EQUAL(150.0, fc::climb_left_at_firing_s(one, 0, plan(), 300.0), 1e-9);
}

// A surfacing for another reason (its Because: line) restarted the clock at
// its arrival: it anchors the chain with tau 0, and a last surfacing of that
// kind has tau 0 itself. A history the rule does not fit (taus spreading
// wider than the longest climb) gets half the longest.
TEST(ForecastSurfacingClock, AnotherReasonAnchorsAMisfitGetsHalf) {
  std::vector<fc::Surfacing> h = history({120.0, 30.0, 200.0}, false, false);
  h[1].reasons = "Hit a waypoint [behavior goto_list]";
  // The last arrived 10970 s after it: tau_last = 170 (not 235, the chain's middle).
  DOUBLES_EQUAL(170.0, fc::climb_left_at_firing_s(h, h.size() - 1, plan(), 300.0), 1e-9);
  CHECK(!fc::surfaced_by_when_secs(h[1], plan()));
  h[2].reasons = "Hit a waypoint [behavior goto_list]";
  DOUBLES_EQUAL(0.0, fc::climb_left_at_firing_s(h, h.size() - 1, plan(), 300.0), 1e-9);
  h[2].reasons = "Every when secs [behavior surface start_when = 9.0]";
  CHECK(fc::surfaced_by_when_secs(h[2], plan()));
  const std::vector<fc::Surfacing> wide = history({0.0, 250.0}, false, false);
  DOUBLES_EQUAL(100.0, fc::climb_left_at_firing_s(wide, wide.size() - 1, plan(), 200.0), 1e-9);
  // No when_secs clock: nothing to seed.
  DOUBLES_EQUAL(0.0, fc::climb_left_at_firing_s(wide, wide.size() - 1, glider::fw::MissionPlan{}, 200.0), 1e-9);
}
