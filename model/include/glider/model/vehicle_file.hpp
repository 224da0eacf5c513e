// SPDX-License-Identifier: Apache-2.0
#pragma once
// The vehicle parameter file (TOML, SI units, keys documented in
// boards/README.md). Init-time only: throws config::ConfigError naming the
// file, the line and the problem.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "glider/config/value_limits.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::model {

VehicleParams load_vehicle_file(const std::filesystem::path& path);
VehicleParams parse_vehicle_text(const std::string& text, const std::string& source_name);

// Every parameter as ("vehicle." + dotted key of the file, value), in file
// order: the `# vehicle.KEY: value` metadata of flight logs (docs/flight-log.md),
// readable back by the tools. The name is "vehicle.name".
std::vector<std::pair<std::string, std::string>> vehicle_metadata(const VehicleParams& v);

// The inverse: a vehicle from a log's `vehicle.*` metadata (keys with the
// "vehicle." prefix removed, as FlightLog::vehicle_metadata() gives them).
// Throws config::ConfigError naming `source_name` if a key is missing or bad.
VehicleParams vehicle_from_metadata(const std::vector<std::pair<std::string, std::string>>& entries,
                                    const std::string& source_name);

// A vehicle file (TOML) holding every parameter of `v`: what load_vehicle_file reads back.
std::string vehicle_file_text(const VehicleParams& v);

// Every number key of the vehicle file with its allowed range.
std::vector<config::KeyRange> vehicle_file_limits();

}  // namespace glider::model
