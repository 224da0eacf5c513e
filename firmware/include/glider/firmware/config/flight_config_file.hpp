// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight software's configuration file (TOML; keys in boards/README.md).
// Init-time only: throws config::ConfigError naming file, line and problem;
// a configuration the firmware cannot fly safely is refused here, before launch.
#include <filesystem>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/flight_software.hpp"

namespace glider::fw {

// Reads the [mission], [limits], [pitch_servo] and [safety] tables. Does not
// reject unknown keys: the caller may read its own tables first, then calls
// doc.reject_unknown_keys().
FlightSoftwareConfig read_flight_config(const config::TomlDocument& doc);

// Every number key read_flight_config reads, with its allowed range.
std::vector<config::KeyRange> flight_config_limits();

}  // namespace glider::fw
