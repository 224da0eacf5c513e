// SPDX-License-Identifier: Apache-2.0
#pragma once
// The target board file the plant hands to glider-firmware: the plant's
// pty devices, its Modbus TCP port, a log directory; and the actuator board
// it names (the plant's actuator board with the bus set to that port).
// glider-firmware reads them exactly as the flight ones (boards/README.md).
#include <filesystem>
#include <string>

#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/hal_linux/keller_depth.hpp"
#include "glider/hal_linux/modbus_board.hpp"

namespace glider::plant {

struct PlantEndpoints {
  std::string host;
  int port = 0;
  std::string gps_device;
  std::string compass_device;
  std::string depth_device;
  std::string modem_device;  // empty: no [modem] table
  std::string modem_vehicle_name;
  hal_linux::KellerConfig keller;
  std::filesystem::path log_directory;
  // The board's [vehicle]: what the flight software must know of the
  // vehicle, here the model's, exactly as glider-sil derives it.
  fw::app::VehicleSetup vehicle;
  std::string heading_law = "compensated";
};

// Writes `directory`/board.toml and `directory`/actuators.toml; returns the
// board file's path. Throws std::runtime_error when a file cannot be written.
std::filesystem::path write_board_files(const std::filesystem::path& directory, const hal_linux::ModbusBoard& actuators,
                                        const PlantEndpoints& endpoints);

}  // namespace glider::plant
