// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Slocum mission (MiDocument) becomes the configuration the flight
// software flies, or is refused before launch. The supported subset and
// every rule are in docs/missions.md. Harmless things the firmware does not
// do (science sampling, strobe, ...) are warnings; anything that would
// change how safely the vehicle flies, and any mission that cannot be flown
// safely (no abend, a dive beyond the rating or the overdepth limit,
// waypoints missing, never surfacing), is an error: no configuration.
#include <optional>
#include <vector>

#include "glider/config/value_limits.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/firmware/mission_file/mi_document.hpp"

namespace glider::fw::mission_file {

// What the mission is checked against: the vehicle's own limits.
struct MissionVehicle {
  double max_working_depth_m = 100.0;  // f_max_working_depth (comet: 102 m)
  ActuatorLimits limits{};             // pump and slide travel the firmware may use
  double fin_max_rad = 0.25;           // f_fin_safety_max
  double fin_rate_rad_s = 0.1;
  double yaw_gain_per_m = 0.0;  // yaw rate per fin per speed (heading predictor; 0 = unknown)
  bool drop_weight_fitted = false;
};

struct LoadedMission {
  std::optional<FlightSoftwareConfig> config;  // empty: refused
  std::vector<Diagnostic> diagnostics;         // warnings (and errors when refused)
};

// `base` supplies what a Slocum mission does not say (pitch servo gains,
// sensor timeouts, heading and DR settings); the mission overrides the rest.
// Every argument the loader flies, per behavior, with its allowed range (in
// Slocum's units; yo arguments with their d_/c_ prefix). Values outside are
// refused with file:line, argument, value and range.
struct ArgumentRange {
  std::string behavior;
  std::string argument;
  config::Range range;
};
std::vector<ArgumentRange> mission_argument_limits();

LoadedMission load_mission(const MiDocument& doc, const MissionVehicle& vehicle, const FlightSoftwareConfig& base = {});

LoadedMission load_mission_file(const std::filesystem::path& path, const MissionVehicle& vehicle,
                                const FlightSoftwareConfig& base = {});

}  // namespace glider::fw::mission_file
