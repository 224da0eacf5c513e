// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one mission setup of the flight application, used unchanged by
// glider-firmware and glider-sil: a Slocum .mi (with its .ma files) or a TOML
// yo mission becomes the FlightSoftwareConfig flown, checked against the
// vehicle's limits and fitted devices, or is refused before launch with the
// same file:line messages in both programs. Init-time only (allocates; never
// called from the loop).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/firmware/flight_software.hpp"

namespace glider::fw::app {

struct MissionOptions {
  HeadingLaw heading_law = HeadingLaw::kCompensated;
  bool flight_model_dr = false;  // kFlightModel dead reckoning: needs the setup's alpha table
  std::int32_t legs = 0;         // .mi: override num_legs_to_run (0: the mission's)
  // The heading autopilot the mission's own settings start from: a study's loop (the replay of
  // a real log's identified gains). Empty: `heading_law` with the vehicle's fin (the flight's).
  std::optional<HeadingControlConfig> heading;
};

struct PreparedMission {
  std::optional<FlightSoftwareConfig> config;         // empty: refused
  std::vector<mission_file::Diagnostic> diagnostics;  // .mi findings, each with file:line
  std::string refusal;                                // why it was refused (file[:line]: ...)
  bool slocum = false;                                // a .mi mission
  double sil_max_sim_time_s = 0.0;                    // TOML [sil] max_sim_time_s (0: not given); SIL only
};

PreparedMission prepare_mission(const std::filesystem::path& mission_path, const VehicleSetup& setup,
                                const MissionOptions& options);

// The lines both programs print for a prepared mission, in order: every
// diagnostic (errors only when `errors_only`), then the refusal if any.
std::vector<std::string> mission_messages(const PreparedMission& mission, bool errors_only);

}  // namespace glider::fw::app
