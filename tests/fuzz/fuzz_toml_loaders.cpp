// SPDX-License-Identifier: Apache-2.0
// Every TOML loader on arbitrary text: the first byte picks the loader
// (mission, vehicle, environment), the rest is the file. A bad file is a
// ConfigError; anything else escaping, or a crash, is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/vehicle_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: {
        const auto doc = glider::config::TomlDocument::parse(text, "fuzz.toml");
        glider::fw::read_flight_config(doc);
        doc.reject_unknown_keys();
        break;
      }
      case 1:
        glider::model::parse_vehicle_text(text, "fuzz.toml");
        break;
      default:
        glider::model::parse_environment_text(text, "fuzz.toml");
        break;
    }
  } catch (const glider::config::ConfigError&) {
  }
  return 0;
}
