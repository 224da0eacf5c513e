// SPDX-License-Identifier: Apache-2.0
// A SIL deployment of 12 days (a log a day, thinned like real logs) in which
// the drag grows linearly (fouling) and the buoyancy offset steps once (a
// lost weight), hidden values drawn by seed: the deployment diagnosis must
// find the trend and the step, and nothing else that changes.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "glider/diagnose/deployment_diagnosis.hpp"
#include "hidden_effect_flight.hpp"

using namespace glider;

namespace {

constexpr double kDay = 86400.0;

struct HiddenHistory {
  double drag_at_start = 0.0, drag_per_day = 0.0;  // ratio to nominal cd0
  double offset_before_g = 0.0, step_g = 0.0, step_day = 0.0;
  double drag(double day) const { return drag_at_start + drag_per_day * day; }
  double offset_g(double day) const { return day < step_day ? offset_before_g : offset_before_g + step_g; }
};

// One day's log: the flown vehicle that day, the nominal one logged.
diagnose::SegmentInput fly_day(const HiddenHistory& truth, int day, std::uint64_t seed) {
  model::VehicleParams flown = hidden::we01();
  flown.hydro.cd0 *= truth.drag(day);
  flown.buoyancy_offset_kg = truth.offset_g(day) * 1e-3;
  fw::FlightSoftwareConfig config =
      fw::read_flight_config(config::TomlDocument::load(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"));
  config.mission.yos = 6;
  config.mission.dive_to_m = 80.0;
  config.mission.max_depth_m = 95.0;
  sil::ScenarioOptions options;
  options.seed = seed;
  options.environment = model::still_water(1025.0);
  options.logged_vehicle = hidden::we01();
  options.log_gaps = hidden::real_log_gaps();
  options.log_path = std::string(GLIDER_TEST_OUTPUT_DIR) + "/deployment_day" + std::to_string(day) + ".csv";
  const sil::ScenarioResult flight = sil::run_scenario(flown, config, options);
  CHECK_TRUE_TEXT(flight.completed, options.log_path.c_str());
  diagnose::SegmentInput in;
  in.name = "day " + std::to_string(day);
  in.time_offset_s = day * kDay;
  in.observations = diagnose::prepare_observations(flightlog::read_flight_log(options.log_path));
  return in;
}

const diagnose::EffectHistory* history_of(const diagnose::DeploymentDiagnosis& d, diagnose::Effect e) {
  for (const auto& h : d.effects) {
    if (h.effect == e) return &h;
  }
  return nullptr;
}

}  // namespace

TEST_GROUP(DiagnoseDeployment) { std::mt19937_64 rng{20261125}; };

TEST(DiagnoseDeployment, DragTrendAndBuoyancyStepOverTwelveDays) {
  HiddenHistory truth;
  truth.drag_at_start = hidden::uniform(rng, 1.0, 1.15);
  truth.drag_per_day = hidden::uniform(rng, 0.015, 0.04);
  truth.offset_before_g = hidden::uniform(rng, -15.0, 15.0);
  truth.step_g = hidden::uniform(rng, 30.0, 60.0) * (rng() % 2 ? 1.0 : -1.0);
  truth.step_day = std::floor(hidden::uniform(rng, 3.0, 9.0)) + 0.5;
  std::vector<diagnose::SegmentInput> segments;
  for (int day = 0; day < 12; ++day) segments.push_back(fly_day(truth, day, 100 + static_cast<std::uint64_t>(day)));
  const diagnose::DeploymentDiagnosis d = diagnose_deployment(hidden::we01(), segments);
  LONGS_EQUAL(12, d.diagnosed);

  const auto* drag = history_of(d, diagnose::Effect::kDragChange);
  const auto* offset = history_of(d, diagnose::Effect::kBuoyancyOffset);
  CHECK_TEXT(drag != nullptr, "drag_change is not an effect of the deployment");
  CHECK_TEXT(offset != nullptr, "buoyancy_offset is not an effect of the deployment");
  char text[320];
  std::snprintf(text, sizeof text, "hidden drag %.3f + %.4f/day; found %s", truth.drag_at_start, truth.drag_per_day,
                drag->trend.describe("ratio").c_str());
  UT_PRINT(text);
  std::snprintf(text, sizeof text, "hidden offset %.1f g, step %+.1f g at day %.1f; found %s", truth.offset_before_g,
                truth.step_g, truth.step_day, offset->trend.describe("g").c_str());
  UT_PRINT(text);

  // The fouling: a line, its rate within 15 % and inside its interval.
  STRCMP_EQUAL("linear", to_string(drag->trend.shape));
  DOUBLES_EQUAL(truth.drag_per_day, drag->trend.slope_per_day.value, 0.15 * truth.drag_per_day);
  CHECK(drag->trend.slope_per_day.low < truth.drag_per_day && truth.drag_per_day < drag->trend.slope_per_day.high);
  DOUBLES_EQUAL(truth.drag_at_start, drag->trend.at_start.value, 0.05);

  // The lost weight: a step between the right two days, its size within 8 g
  // and inside its interval.
  STRCMP_EQUAL("step", to_string(offset->trend.shape));
  CHECK(offset->trend.step_before_s < truth.step_day * kDay && truth.step_day * kDay < offset->trend.step_after_s);
  DOUBLES_EQUAL(truth.step_g, offset->trend.step_change.value, 8.0);
  CHECK(offset->trend.step_change.low < truth.step_g && truth.step_g < offset->trend.step_change.high);

  // Nothing else changes in this water: any other effect is constant.
  for (const auto& h : d.effects) {
    if (&h == drag || &h == offset) continue;
    std::snprintf(text, sizeof text, "%s: %s", info(h.effect).id, h.trend.describe(info(h.effect).unit).c_str());
    UT_PRINT(text);
    CHECK_TEXT(h.trend.shape == diagnose::TrendShape::kConstant || h.trend.shape == diagnose::TrendShape::kNone, text);
  }
}
