// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading plane's hidden-effect flights: SIL flies the heading-hold
// mission (boards/missions/heading_hold.mi) on a comet vehicle with an effect
// the log does not state, with Slocum's law at the flown gains; the log
// states the nominal comet vehicle and the configured gains (as a real
// Slocum header does), is logged at a Slocum's cycle, and the diagnosis
// sees only the CSV.
#include <CppUTest/TestHarness.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "glider/diagnose/heading_diagnose.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "hidden_effect_flight.hpp"

namespace glider::hidden {

// With WE01's lift and drag (slocum_we01.toml), which slocum_comet.toml
// flew until issue 24 gave it the comet's own (0.30 m/s instead of 0.40):
// these flights and their thresholds were calibrated at that speed, and the
// yaw rates scale with it (re-tuning them to the comet's polar: open).
inline model::VehicleParams comet() {
  model::VehicleParams v = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_comet.toml");
  v.hydro = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml").hydro;
  return v;
}

// The gains the log's header states (Slocum's, as in the comet logs).
inline fw::HeadingControlConfig configured_slocum_law() {
  fw::HeadingControlConfig law;
  law.law = fw::HeadingLaw::kSlocum;
  return law;
}

// Subtracts `delta` from every m_roll value of a CSV log: a roll sensor that
// does not show a mis-trim of that size.
inline void hide_roll(const std::string& path, double delta_rad) {
  std::ifstream in(path);
  std::ostringstream out;
  std::string line;
  int column = -1;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || column == -2) {
      out << line << '\n';
      continue;
    }
    std::vector<std::string> fields;
    std::stringstream split(line);
    std::string f;
    while (std::getline(split, f, ',')) fields.push_back(f);
    if (column == -1) {
      for (std::size_t i = 0; i < fields.size(); ++i) {
        if (fields[i] == "m_roll") column = static_cast<int>(i);
      }
      if (column == -1) column = -2;
      out << line << '\n';
      continue;
    }
    const auto c = static_cast<std::size_t>(column);
    if (c < fields.size() && !fields[c].empty()) fields[c] = std::to_string(std::stod(fields[c]) - delta_rad);
    for (std::size_t i = 0; i < fields.size(); ++i) out << (i ? "," : "") << fields[i];
    if (!line.empty() && line.back() == ',') out << ',';
    out << '\n';
  }
  in.close();
  std::ofstream(path) << out.str();
}

// The comet logs' dbd cycle (median 4.3-4.5 s, tests/data/real/README.md).
inline constexpr hal::Micros kSlocumCycleUs = 4'000'000;

struct HeadingOutcome {
  diagnose::HeadingDiagnosis diagnosis;
  std::string log_path;
};

// Flies `flown` with `law` (the SIL's Slocum law at the flown gains), logs
// the nominal comet and the configured gains; `hidden_roll_rad` is taken out
// of the logged m_roll; `water` the SIL flies in (still by default);
// `compass_delay_s` the compass's dead time (sil::SensorNoise).
inline HeadingOutcome fly_heading_and_diagnose(const model::VehicleParams& flown, const fw::HeadingControlConfig& law,
                                               const std::string& name, double hidden_roll_rad = 0.0,
                                               const model::Environment& water = {}, double compass_delay_s = 0.0) {
  const model::VehicleParams nominal = comet();
  fw::FlightSoftwareConfig base;
  base.heading = law;
  const auto loaded = fw::mission_file::load_mission_file(GLIDER_SOURCE_DIR "/boards/missions/heading_hold.mi",
                                                          sil::mission_vehicle(flown, 102.0), base);
  CHECK_TRUE_TEXT(loaded.config.has_value(), name.c_str());
  const fw::HeadingControlConfig stated = configured_slocum_law();
  sil::ScenarioOptions options;
  options.logged_vehicle = nominal;
  // Like a real Slocum log where it matters here: the flight computer's
  // cycle is the log's (~4 s, every command and fin reading logged), not a
  // 1 Hz loop thinned afterwards (which would hide the commands between rows).
  options.period_us = kSlocumCycleUs;
  options.environment = water;
  options.noise.heading_delay_s = compass_delay_s;
  // The plant at the accuracy reference step (0.1 s), as the heading replays:
  // yaw_time_constant reads ~7 % short either way (6.20 -> 5.79), its interval
  // only just holds the truth at 0.1 s and misses it by 0.01 s at 1 s (issue 14 part 3).
  options.integration_step_s = 0.1;
  options.log_path = std::string(GLIDER_TEST_OUTPUT_DIR) + "/hidden_heading_" + name + ".csv";
  options.metadata.emplace_back(
      "settings_at_file_open", "f_fin_safety_max=" + std::to_string(nominal.heading.fin_max_rad) +
                                   " u_hd_fin_ap_gain=" + std::to_string(stated.gain) + " u_hd_fin_ap_igain=" +
                                   std::to_string(stated.igain) + " u_hd_fin_ap_dgain=" + std::to_string(stated.dgain) +
                                   " u_heading_rate_deadband=" + std::to_string(stated.rate_deadband_rad_s));
  const sil::ScenarioResult flight = sil::run_scenario(flown, *loaded.config, options);
  CHECK_TRUE_TEXT(flight.completed, name.c_str());
  if (hidden_roll_rad != 0.0) hide_roll(options.log_path, hidden_roll_rad);
  const flightlog::FlightLog log = flightlog::read_flight_log(options.log_path);
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& m : log.vehicle_metadata()) entries.emplace_back(m.key, m.value);
  const model::VehicleParams from_log = model::vehicle_from_metadata(entries, options.log_path);
  return {diagnose::diagnose_heading(from_log, log), options.log_path};
}

// The finding of `effect` in a diagnosis, or nullptr.
inline const diagnose::HeadingFinding* finding(const diagnose::HeadingDiagnosis& d, diagnose::HeadingEffect effect) {
  for (const diagnose::LinkFit* link : {&d.servo, &d.yaw, &d.autopilot}) {
    for (const diagnose::HeadingFinding& f : link->findings) {
      if (f.effect == effect) return &f;
    }
  }
  return nullptr;
}

}  // namespace glider::hidden
