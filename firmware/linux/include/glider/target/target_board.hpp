// SPDX-License-Identifier: Apache-2.0
#pragma once
// The board file of the firmware on the Linux target (boards/target/): which
// devices the glider has and where, and how the loop runs. Paths to the
// other board files are relative to this file.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glider/firmware/app/mission_setup.hpp"
#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/hal_linux/hwmon_power.hpp"
#include "glider/hal_linux/keller_depth.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/hal_linux/serial_modem.hpp"
#include "glider/target/realtime_loop.hpp"

namespace glider::target {

struct SerialSensorConfig {
  std::string device;
  int baud = 9600;
  hal::Micros stale_after_us = 5'000'000;
};

struct DepthConfig {
  hal_linux::BusConfig bus;  // RTU
  hal_linux::KellerConfig keller;
};

// [modem]: the Iridium modem and what the vehicle says and dials (docs/comms.md).
struct ModemBoardConfig {
  hal_linux::SerialModemConfig line;
  std::string vehicle_name;      // default: the board's name
  std::string primary_number;    // RUDICS number dialled first
  std::string secondary_number;  // "" none
  std::vector<std::string> dialog_sensors{"m_battery", "m_depth", "m_water_vx", "m_water_vy"};
  // modem.reply_window_s (fw::comms::CommsConfig::reply_window_s); absent: CommsConfig's default.
  std::optional<double> reply_window_s;
};

struct TargetBoard {
  std::string source;
  std::string name;
  RealtimeOptions loop;
  std::filesystem::path actuators_board;
  std::optional<std::filesystem::path> gpio_board;  // absent: no leak detect or drop weight (bench only)
  SerialSensorConfig gps;
  SerialSensorConfig compass;
  DepthConfig depth;
  std::optional<hal_linux::PowerMonitorConfig> power;  // absent: no battery readings (bench only)
  std::optional<ModemBoardConfig> modem;               // absent: the vehicle never calls
  std::filesystem::path log_directory = "/var/lib/glider/logs";
  // What the flight application needs of the vehicle ([vehicle]); its fitted
  // devices are the ones this board configures: [gpio] (leak line and drop
  // weight), [power], a [rudder] axis on the actuator board.
  fw::app::VehicleSetup vehicle;
  fw::app::MissionOptions mission_options;  // vehicle.heading_law, vehicle.dead_reckoning
  // A bench or HIL rig, not a vehicle: test options (--time-scale) are allowed.
  bool bench = false;
};

// Init-time only: throws config::ConfigError naming file, line and problem.
TargetBoard load_target_board(const std::filesystem::path& path);
// Every number of the board file and its range, [vehicle] included (the
// bad-value test tries each, tests/unit/test_board_limits.cpp).
std::vector<config::KeyRange> target_board_limits();
TargetBoard parse_target_board(const std::string& text, const std::string& source_name,
                               const std::filesystem::path& relative_to);

}  // namespace glider::target
