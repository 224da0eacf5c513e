// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the diagnosis tools (glider-diagnose, glider-diagnose-deployment)
// take from the user, read the same way in each.
#include <string>
#include <utility>
#include <vector>

#include "glider/diagnose/flight_model.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

struct NominalVehicle {
  model::VehicleParams params;
  std::string source;  // said to the user: "file X", "the log's vehicle.* metadata", ...
};

// Which vehicle a log is diagnosed against: --vehicle FILE, else the log's
// vehicle.* metadata, else the default. Throws std::runtime_error when there
// is none (no file, no metadata, no default).
NominalVehicle nominal_vehicle(const std::string& vehicle_path, const flightlog::FlightLog& log,
                               const std::string& log_path, const std::string& default_vehicle);

// --fit ids as depth-rate effects (the pitch trim is not one: it is always
// judged last). Throws std::invalid_argument naming an unknown id.
std::vector<Effect> depth_rate_effects(const std::vector<std::string>& ids);

// --rename FROM=TO pairs. Throws std::invalid_argument for a malformed one.
std::vector<std::pair<std::string, std::string>> column_renames(const std::vector<std::string>& renames);

}  // namespace glider::diagnose
