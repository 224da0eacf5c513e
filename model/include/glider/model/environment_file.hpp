// SPDX-License-Identifier: Apache-2.0
#pragma once
// The environment file (TOML, keys in boards/README.md): the water the SIL
// flies in. Init-time only; throws config::ConfigError with file and line.
#include <filesystem>
#include <string>
#include <vector>

#include "glider/config/value_limits.hpp"

#include "glider/model/environment.hpp"

namespace glider::model {

Environment load_environment_file(const std::filesystem::path& path);
Environment parse_environment_text(const std::string& text, const std::string& source_name);

// Every number key of the environment file with its allowed range.
std::vector<config::KeyRange> environment_file_limits();

}  // namespace glider::model
