// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the diagnosis tools (glider-diagnose, glider-diagnose-deployment)
// take from the user, read the same way in each.
#include <optional>
#include <stdexcept>
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

// How the user chose the vehicle: --vehicle, --default-vehicle (both may be
// empty) and the boards folder whose gliders.toml says which file
// describes which glider (boards/).
struct VehicleChoice {
  std::string vehicle_path;
  std::string default_vehicle;
  std::string boards_dir;
};

// No vehicle for a log: a refusal of the whole run, never one segment's problem.
class NoVehicle : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Which vehicle a log is diagnosed against: --vehicle FILE, else the log's
// vehicle.* metadata (a SIL log), else --default-vehicle, else the vehicle
// file gliders.toml gives for the glider the log names. Throws NoVehicle when
// there is none: there is no silent default.
NominalVehicle nominal_vehicle(const VehicleChoice& choice, const flightlog::FlightLog& log,
                               const std::string& log_path);

// The glider a log names: a CSV's "# glider:" metadata (first word), else a
// Slocum file name <glider>-<yyyy>-<ddd>-<mission>-<segment> (of the file, or
// of the first such file in a folder).
std::optional<std::string> glider_named_by(const flightlog::FlightLog& log, const std::string& log_path);

// The vehicle file `boards_dir`/gliders.toml gives for `glider`, if any.
std::optional<std::string> vehicle_file_of_glider(const std::string& glider, const std::string& boards_dir);

// --fit ids as depth-rate effects (the pitch trim is not one: it is always
// judged last). Throws std::invalid_argument naming an unknown id.
std::vector<Effect> depth_rate_effects(const std::vector<std::string>& ids);

// --rename FROM=TO pairs. Throws std::invalid_argument for a malformed one.
std::vector<std::pair<std::string, std::string>> column_renames(const std::vector<std::string>& renames);

}  // namespace glider::diagnose
