// SPDX-License-Identifier: Apache-2.0
#pragma once
// A SIL deployment for health: one SIL flight per surfacing interval
// (missions/health_box: ~3 h of 5-40 m yos round a 600 m box), flown by a
// vehicle whose hidden faults follow a plan, its decimated .sbd (sbdlist.dat:
// 24 sensors, every 4 s at most) kept and the full-resolution .dbd deleted,
// as the shore receives them. Shared by the tests (tests/health) and the
// benchmark (benchmarks/health_benchmark.cpp).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <string_view>

#include "glider/firmware/app/mission_setup.hpp"
#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_list.hpp"
#include "glider/health/health.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"

namespace glider::health_sil {

// Heading disturbances that move the fin without a commanded turn (docs/
// health.md, "The fin in disturbed water"): none by default, so a plan
// without them flies bit-identically as before. The SIL's own models: the
// vehicle's random yaw (heading.yaw_disturbance_*: first-order Gauss-
// Markov; the comet logs' calibration is 0.34-0.82 deg/s RMS over 4 s,
// docs/heading-control.md) and the compass's white noise (SensorNoise).
struct Disturbance {
  double yaw_deg_s = 0.0;           // RMS of the random yaw rate (0: none)
  double yaw_correlation_s = 4.0;   // its correlation time
  double compass_noise_deg = -1.0;  // the compass's noise (< 0: the SIL's default, 0.2 deg)
};

// The hidden faults. A surfacing index k flies from day k * hours_apart / 24.
struct FaultPlan {
  double drag_per_day = 0.0;    // cd0 grows by this fraction of nominal per day ...
  double drag_onset_day = 1e9;  // ... from this day
  double step_g = 0.0;          // buoyancy offset change ...
  int step_at = -1;             // ... from this surfacing on (-1: none)
  double fin_factor = 1.0;      // fin yaw gain multiplied ...
  int fin_at = -1;
  double pump_factor = 1.0;  // pump rate multiplied ...
  int pump_at = -1;
  double pump_lag_s = 0.0;  // the displaced volume lags the pump by this ...
  int pump_lag_at = -1;     // ... from this surfacing on
  Disturbance disturbance;  // the water and compass every surfacing flies in (not a fault)
};

inline model::VehicleParams nominal_vehicle() {
  model::VehicleParams v = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  // The SIL flies the file's drag at every speed (n = 0, the file's silence);
  // health is told so, as a pilot who knows the exponent states it. Silent,
  // health flies the diagnosis prior n = 0.1 against the SIL's 0: a -55 g
  // step read -52.7 g [-54.1, -51.3] (the prior's misfit, not health's).
  v.hydro.cd0_reynolds_exponent_stated = true;
  return v;
}

// The vehicle flown in surfacing k.
inline model::VehicleParams flown_vehicle(const FaultPlan& plan, int k, double hours_apart) {
  model::VehicleParams v = nominal_vehicle();
  const double day = k * hours_apart / 24.0;
  if (day > plan.drag_onset_day) v.hydro.cd0 *= 1.0 + plan.drag_per_day * (day - plan.drag_onset_day);
  if (plan.step_at >= 0 && k >= plan.step_at) v.buoyancy_offset_kg += plan.step_g * 1e-3;
  if (plan.fin_at >= 0 && k >= plan.fin_at) v.heading.fin_yaw_gain_per_m *= plan.fin_factor;
  if (plan.pump_at >= 0 && k >= plan.pump_at) v.ballast.rate_m3_s *= plan.pump_factor;
  if (plan.pump_lag_at >= 0 && k >= plan.pump_lag_at) v.ballast.lag_s = plan.pump_lag_s;
  if (plan.disturbance.yaw_deg_s > 0.0) {
    v.heading.yaw_disturbance_rad_s = plan.disturbance.yaw_deg_s * std::numbers::pi / 180.0;
    v.heading.yaw_disturbance_correlation_s = plan.disturbance.yaw_correlation_s;
  }
  return v;
}

// The launch heading's spread about 180 deg the tests and the benchmark fly
// by default: the box's first leg is north, so every surfacing starts with
// one long turn (docs/health.md, "Fin effectiveness on any launch heading").
constexpr int kDefaultLaunchSpreadDeg = 10;

// Flies surfacing k into `dir` (files <vehicle>-1970-000-<k>-<segment>.sbd,
// times from 0: place them with seconds_apart). Empty string: done; else why not.
// `sbdlist`: the .sbd's list (empty: tests/health/sbdlist.dat). The mission
// is `mission_path` under tests/health/missions, launched heading
// `heading_deg`: fly_surfacing and fly_transect below.
inline std::string fly_mission(const std::string& dir, const FaultPlan& plan, int k, double hours_apart,
                               std::uint64_t seed, std::string_view sbdlist, const std::string& mission_path,
                               double heading_deg) {
  const model::VehicleParams flown = flown_vehicle(plan, k, hours_apart);
  // The firmware is set up for the nominal vehicle (what the pilot's files say).
  const model::VehicleParams nominal = nominal_vehicle();
  sil::ScenarioOptions options;
  options.seed = seed;
  options.environment = model::still_water(nominal.trim_density_kg_m3);
  if (plan.disturbance.compass_noise_deg >= 0.0)
    options.noise.heading_rad = plan.disturbance.compass_noise_deg * std::numbers::pi / 180.0;
  const fw::app::VehicleSetup setup =
      sil::vehicle_setup(nominal, options.fitted, 100.0, false, options.environment.water.at(0.0, 0.0).density_kg_m3);
  const fw::app::PreparedMission mission = fw::app::prepare_mission(
      GLIDER_SOURCE_DIR "/tests/health/missions/" + mission_path, setup, fw::app::MissionOptions{});
  if (!mission.config) return "mission refused: " + mission.refusal;
  const fw::SlocumListResult sbd = sbdlist.empty() ? fw::read_slocum_list(GLIDER_SOURCE_DIR "/tests/health/sbdlist.dat")
                                                   : fw::parse_slocum_list(sbdlist, "sbdlist");
  if (!sbd.error.empty()) return sbd.error;
  std::filesystem::create_directories(dir);
  const fw::SlocumMissionNumbers numbers = fw::next_slocum_mission(dir, nominal.name, 0);
  options.max_sim_time_s = 6.0 * 3600.0;
  options.heading_deg = heading_deg;
  options.slocum_directory = dir;
  options.slocum.vehicle = nominal.name;
  options.slocum.mission_name = std::filesystem::path(mission_path).filename().string();
  options.slocum.mission_of_day = numbers.mission_of_day;
  options.slocum.mission_number = numbers.mission_number;
  options.slocum.sbd = sbd.selection;
  const sil::ScenarioResult result = sil::run_scenario(flown, *mission.config, options);
  if (!result.error.empty()) return result.error;
  if (!result.completed) return "surfacing " + std::to_string(k) + " did not complete its mission";
  // Only the decimated files come home.
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".dbd") std::filesystem::remove(entry.path());
  }
  return {};
}

// The box (missions/health_box). The glider starts heading 180 deg +-
// `launch_spread_deg` (whole degrees drawn from the seed; 180: any heading,
// as a pilot's glider surfaces wherever the mission left it).
inline std::string fly_surfacing(const std::string& dir, const FaultPlan& plan, int k, double hours_apart,
                                 std::uint64_t seed, std::string_view sbdlist = {},
                                 int launch_spread_deg = kDefaultLaunchSpreadDeg) {
  const auto spread = static_cast<std::uint64_t>(launch_spread_deg);
  const double heading_deg = 180.0 + static_cast<double>(seed % (2 * spread + 1)) - static_cast<double>(spread);
  return fly_mission(dir, plan, k, hours_apart, seed, sbdlist, "health_box/missions/box.mi", heading_deg);
}

// Flies surfacing k as a straight transect (missions/health_line: ~3 h of
// the same yos towards a waypoint due south, never reached), launched heading
// 180 + `turn_deg`: 0 never turns, else one turn of that size at the start
// (docs/health.md, "The fin is judged only on segments that turn").
inline std::string fly_transect(const std::string& dir, const FaultPlan& plan, int k, double hours_apart,
                                std::uint64_t seed, double turn_deg) {
  return fly_mission(dir, plan, k, hours_apart, seed, {}, "health_line/missions/line.mi", 180.0 + turn_deg);
}

// Health's options for a deployment flown into dir/sbd, its state dir/state.json.
inline health::HealthOptions health_options(const std::string& dir, double hours_apart) {
  health::HealthOptions o;
  o.inputs = {dir + "/sbd"};
  o.state_path = dir + "/state.json";
  o.vehicle = nominal_vehicle();
  o.vehicle_source = "slocum_we01.toml";
  o.seconds_apart = hours_apart * 3600.0;
  return o;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

}  // namespace glider::health_sil
