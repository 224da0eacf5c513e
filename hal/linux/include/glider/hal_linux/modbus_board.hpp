// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a Modbus board file says (boards/modbus_actuators.md): the bus, its
// timing budget and, per actuator axis, where it lives and how it scales.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glider/config/value_limits.hpp"

namespace glider::hal_linux {

enum class Transport { kTcp, kRtu };

struct BusConfig {
  Transport transport = Transport::kTcp;
  // TCP. The host must be numeric on the target (no DNS lookups in flight).
  std::string host = "127.0.0.1";
  int port = 1502;
  // RTU (serial line).
  std::string device = "/dev/ttyUSB0";
  int baud = 19200;
  char parity = 'N';  // 'N', 'E' or 'O'
  int data_bits = 8;
  int stop_bits = 1;
  // modbus_rtu_set_serial_mode(RS485). Fails with ENOTTY on a pty or a
  // plain RS-232 port: reported as a warning, never fatal.
  bool rs485 = false;
  // Timing: every attempt waits at most response_timeout_ms (+ byte
  // timeouts); a failed transaction is retried `retries` times; all the
  // transactions of one control period together block at most
  // cycle_budget_ms (the rest fail fast and are reported as faults).
  int response_timeout_ms = 100;
  int byte_timeout_ms = 10;
  int retries = 2;
  int cycle_budget_ms = 400;
  int cycle_period_ms = 1000;
};

struct AxisConfig {
  std::string name;  // "pump" or "slide"
  std::string unit;  // "cc" or "in"
  int slave = 1;
  int base_address = 0;
  double counts_per_unit = 1.0;
  double min = 0.0;  // command limits (software)
  double max = 0.0;
  double rate = 0.0;        // commanded speed, unit/s
  double travel_min = 0.0;  // limit switches (mechanical travel)
  double travel_max = 0.0;
  double max_rate = 0.0;  // fastest the mechanism can move, unit/s
};

struct ModbusBoard {
  std::string source;  // file it was read from
  BusConfig bus;
  AxisConfig pump;
  AxisConfig slide;
  std::optional<AxisConfig> rudder;  // [rudder], deg, + turns clockwise; absent on boards without a fin drive
};

// Init-time only: throws config::ConfigError naming file, line and problem.
ModbusBoard load_modbus_board(const std::filesystem::path& path);
ModbusBoard parse_modbus_board(const std::string& text, const std::string& source_name);
// Every number of an actuator board file and its range (the bad-value test
// tries each, tests/unit/test_board_limits.cpp).
const std::vector<config::KeyRange>& modbus_board_limits();

// Command-line overrides of the board's bus: "HOST:PORT" or a device path.
// Throws config::ConfigError on a malformed HOST:PORT.
void use_tcp_endpoint(BusConfig& bus, const std::string& host_port);
// "" when `host_port` is a numeric IPv4 HOST:PORT use_tcp_endpoint takes,
// else what is wrong (naming the value): for the programs' option checks.
std::string tcp_endpoint_problem(const std::string& host_port);
void use_rtu_device(BusConfig& bus, const std::string& device);

// "tcp 127.0.0.1:1502" / "rtu /dev/ttyUSB0 19200 8N1".
std::string describe(const BusConfig& bus);

}  // namespace glider::hal_linux
