// SPDX-License-Identifier: Apache-2.0
// Every TOML loader on arbitrary text: the first byte picks the loader
// (mission, vehicle, environment, actuator board, target board), the rest is
// the file. A bad file is a
// ConfigError; anything else escaping, or a crash, is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/target/target_board.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 5) {
      case 0: {
        const auto doc = glider::config::TomlDocument::parse(text, "fuzz.toml");
        glider::fw::read_flight_config(doc);
        doc.reject_unknown_keys();
        break;
      }
      case 1:
        glider::model::parse_vehicle_text(text, "fuzz.toml");
        break;
      case 2:
        glider::model::parse_environment_text(text, "fuzz.toml");
        break;
      case 3:
        glider::hal_linux::parse_modbus_board(text, "fuzz.toml");
        break;
      default:  // actuators.board and gpio.board relative to the shipped target boards
        glider::target::parse_target_board(text, "fuzz.toml", GLIDER_SOURCE_DIR "/boards/target");
        break;
    }
  } catch (const glider::config::ConfigError&) {
  }
  return 0;
}
