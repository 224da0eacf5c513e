// SPDX-License-Identifier: Apache-2.0
#pragma once
// The environment file (TOML, keys in boards/README.md): the water the SIL
// flies in. Init-time only; throws config::ConfigError with file and line.
#include <filesystem>
#include <string>

#include "glider/model/environment.hpp"

namespace glider::model {

Environment load_environment_file(const std::filesystem::path& path);
Environment parse_environment_text(const std::string& text, const std::string& source_name);

}  // namespace glider::model
