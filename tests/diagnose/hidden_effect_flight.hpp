// SPDX-License-Identifier: Apache-2.0
#pragma once
// What every hidden-effect test does: fly the project's model in SIL with an
// effect the logged (nominal) vehicle does not know about, write the CSV, and
// hand only the CSV to the diagnosis. Shared by the hidden-effect test files
// so they fly the same mission and read the log the same way.
#include <CppUTest/TestHarness.h>

#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/scenario.hpp"
#include "hidden_truth.hpp"

namespace glider::hidden {

struct Outcome {
  diagnose::Diagnosis diagnosis;
  std::string log_path;
};

// How a hidden-effect flight is flown and logged.
struct FlightSetup {
  double dive_to_m = 80.0;  // 6 yos between 5 m and this depth
  sil::LogGaps gaps{};      // thin the log like a real Slocum log (off by default)
  // The vehicle the log states (the diagnosis's nominal): default WE01.
  std::optional<model::VehicleParams> logged;
};

// Flies the flown vehicle in the water given, logging the nominal vehicle;
// diagnoses the CSV alone.
inline Outcome fly_and_diagnose(const model::VehicleParams& flown, const model::Environment& water,
                                const std::string& name, const FlightSetup& setup) {
  const model::VehicleParams nominal =
      setup.logged.value_or(model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml"));
  fw::FlightSoftwareConfig config =
      fw::read_flight_config(config::TomlDocument::load(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"));
  config.mission.yos = 6;
  config.mission.dive_to_m = setup.dive_to_m;
  config.mission.max_depth_m = setup.dive_to_m + 15.0;
  sil::ScenarioOptions options;
  options.environment = water;
  options.logged_vehicle = nominal;
  options.log_gaps = setup.gaps;
  options.log_path = std::string(GLIDER_TEST_OUTPUT_DIR) + "/hidden_" + name + ".csv";
  const sil::ScenarioResult flight = sil::run_scenario(flown, config, options);
  CHECK_TRUE_TEXT(flight.completed, name.c_str());
  const flightlog::FlightLog log = flightlog::read_flight_log(options.log_path);
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& m : log.vehicle_metadata()) entries.emplace_back(m.key, m.value);
  const model::VehicleParams from_log = model::vehicle_from_metadata(entries, options.log_path);
  return {diagnose::diagnose(from_log, diagnose::prepare_observations(log)), options.log_path};
}

inline Outcome fly_and_diagnose(const model::VehicleParams& flown, const model::Environment& water,
                                const std::string& name, double dive_to_m = 80.0, const sil::LogGaps& gaps = {}) {
  return fly_and_diagnose(flown, water, name, FlightSetup{dive_to_m, gaps, std::nullopt});
}

// Thinning like the real logs: rows every 2-5 s, sci_* missing in 5 % of
// them, 20-200 s without rows at each surfacing.
inline sil::LogGaps real_log_gaps() {
  sil::LogGaps gaps;
  gaps.enabled = true;
  return gaps;
}

inline model::VehicleParams we01() {
  model::VehicleParams v = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  // The SIL flies the file's drag at every speed (n = 0, the file's
  // silence): stated, so a diagnosis against it flies the SIL's drag, not
  // the prior for a real glider (a hidden 0.0316/day drag trend read
  // 0.0298 [0.02968, 0.02992] with the prior).
  v.hydro.cd0_reynolds_exponent_stated = true;
  return v;
}

}  // namespace glider::hidden
