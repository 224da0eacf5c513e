// SPDX-License-Identifier: Apache-2.0
#include "glider/target/target_board.hpp"

#include <cmath>

#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/serial_port.hpp"

namespace glider::target {
namespace {

using config::TomlDocument;

using config::Range;

// Physical ranges of the board file's numbers (value_limits.hpp): refusals
// name file:line:column, key, value and range.
constexpr Range kStaleAfter{0.1, 600.0, "s"};
constexpr Range kVoltage{1.0, 100.0, "V"};
constexpr Range kBaud{300.0, 4'000'000.0, "baud"};

// Every number of the board file but its [vehicle] table's (read_vehicle_setup's own).
const std::vector<config::KeyRange>& limits() {
  static const std::vector<config::KeyRange> table{
      {"loop.priority", {1.0, 99.0, ""}},
      {"loop.stats_every_s", {1.0, 86400.0, "s"}},
      {"gps.baud", kBaud},
      {"gps.stale_after_s", kStaleAfter},
      {"compass.baud", kBaud},
      {"compass.stale_after_s", kStaleAfter},
      {"depth.baud", kBaud},
      {"modem.baud", kBaud},
      // After each answer, once the shore has typed (docs/comms.md, the reply window); 0: keystroke_wait_time only.
      {"modem.reply_window_s", {0.0, 600.0, "s"}},
      {"depth.response_timeout_ms", {1.0, 1000.0, "ms"}},
      {"depth.retries", {0.0, 5.0, ""}},
      {"depth.cycle_budget_ms", {1.0, 1000.0, "ms (and at least depth.response_timeout_ms)"}},
      {"depth.slave", {1.0, 247.0, ""}},
      {"depth.surface_pressure_bar", {0.0, 1.2, "bar (0: gauge transmitter)"}},
      {"depth.water_density_kg_m3", {990.0, 1050.0, "kg/m^3"}},
      {"depth.max_pressure_bar", {0.1, 1200.0, "bar"}},
      {"power.charge_used_at_start_amphr", {0.0, 10000.0, "Ah"}},
      {"power.min_voltage_v", kVoltage},
      {"power.max_voltage_v", kVoltage},
  };
  return table;
}

double number_or(const TomlDocument& doc, const std::string& key, double fallback) {
  return doc.number_or(key, fallback, config::range_of(limits(), key));
}

// An integer key of the table: a whole number in its range.
int integer_in(const TomlDocument& doc, const std::string& key, std::int64_t fallback) {
  const Range& range = config::range_of(limits(), key);
  return static_cast<int>(
      doc.integer_or(key, fallback, static_cast<std::int64_t>(range.min), static_cast<std::int64_t>(range.max)));
}

int baud(const TomlDocument& doc, const std::string& key, int fallback) {
  const int value = integer_in(doc, key, fallback);
  if (!hal_linux::supported_baud(value)) doc.fail(key, "not a standard baud rate");
  return value;
}

std::filesystem::path board_path(const TomlDocument& doc, const std::string& key,
                                 const std::filesystem::path& relative_to) {
  std::filesystem::path path = relative_to / doc.string(key);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) doc.fail(key, "no such file: " + path.string());
  return path;
}

SerialSensorConfig read_serial(const TomlDocument& doc, const std::string& table, int default_baud,
                               double default_stale_s) {
  SerialSensorConfig sensor;
  sensor.device = doc.string(table + ".device");
  sensor.baud = baud(doc, table + ".baud", default_baud);
  sensor.stale_after_us =
      static_cast<hal::Micros>(std::llround(number_or(doc, table + ".stale_after_s", default_stale_s) * 1e6));
  return sensor;
}

DepthConfig read_depth(const TomlDocument& doc) {
  DepthConfig depth;
  hal_linux::BusConfig& bus = depth.bus;
  bus.transport = hal_linux::Transport::kRtu;
  bus.device = doc.string("depth.device");
  bus.baud = baud(doc, "depth.baud", 9600);  // Keller's default line: 9600 8N1
  bus.response_timeout_ms = integer_in(doc, "depth.response_timeout_ms", 100);
  bus.retries = integer_in(doc, "depth.retries", 1);
  bus.cycle_budget_ms = integer_in(doc, "depth.cycle_budget_ms", 250);
  if (bus.cycle_budget_ms < bus.response_timeout_ms) {
    doc.fail("depth.cycle_budget_ms", "value " + std::to_string(bus.cycle_budget_ms) +
                                          " must allow at least one response timeout (depth.response_timeout_ms " +
                                          std::to_string(bus.response_timeout_ms) + " ms)");
  }
  hal_linux::KellerConfig& keller = depth.keller;
  keller.slave = integer_in(doc, "depth.slave", 1);
  keller.surface_pressure_bar = number_or(doc, "depth.surface_pressure_bar", keller.surface_pressure_bar);
  keller.water_density_kg_m3 = number_or(doc, "depth.water_density_kg_m3", keller.water_density_kg_m3);
  keller.max_pressure_bar = number_or(doc, "depth.max_pressure_bar", keller.max_pressure_bar);
  return depth;
}

hal_linux::PowerMonitorConfig read_power(const TomlDocument& doc) {
  hal_linux::PowerMonitorConfig power;
  power.hwmon_name = doc.string_or("power.hwmon_name", power.hwmon_name);
  power.charge_used_at_start_amphr = number_or(doc, "power.charge_used_at_start_amphr", 0.0);
  power.min_voltage_v = number_or(doc, "power.min_voltage_v", power.min_voltage_v);
  power.max_voltage_v = number_or(doc, "power.max_voltage_v", power.max_voltage_v);
  if (power.min_voltage_v >= power.max_voltage_v) {
    doc.fail("power.max_voltage_v", "value " + config::show_value(power.max_voltage_v) +
                                        " must be above power.min_voltage_v (" +
                                        config::show_value(power.min_voltage_v) + " V)");
  }
  return power;
}

// A dialled number: digits (and a leading +), at most 32 of them.
std::string phone_number(const TomlDocument& doc, const std::string& key, const std::string& fallback) {
  std::string number = doc.string_or(key, fallback);
  const bool digits = number.find_first_not_of("+0123456789") == std::string::npos && number.size() <= 32;
  if (!digits) doc.fail(key, "must be a phone number (digits, at most 32)");
  return number;
}

ModemBoardConfig read_modem(const TomlDocument& doc, const std::string& board_name) {
  ModemBoardConfig modem;
  modem.line.device = doc.string("modem.device");
  modem.line.baud = baud(doc, "modem.baud", 19200);
  modem.line.dcd_wired = doc.boolean_or("modem.dcd", false);
  modem.vehicle_name = doc.string_or("modem.vehicle_name", board_name);
  if (modem.vehicle_name.empty() || modem.vehicle_name.size() >= 40)
    doc.fail("modem.vehicle_name", "1 to 39 characters");
  modem.primary_number = phone_number(doc, "modem.primary_number", "");
  if (modem.primary_number.empty()) doc.fail("modem.primary_number", "a number to dial is needed");
  modem.secondary_number = phone_number(doc, "modem.secondary_number", "");
  if (doc.has("modem.reply_window_s")) modem.reply_window_s = number_or(doc, "modem.reply_window_s", 0.0);
  const std::string sensors = doc.string_or("modem.dialog_sensors", "");
  if (!sensors.empty()) {
    modem.dialog_sensors.clear();
    std::size_t from = 0;
    while (from <= sensors.size()) {
      const std::size_t comma = sensors.find(',', from);
      const std::string name = sensors.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
      if (name.empty() || name.size() >= 40) doc.fail("modem.dialog_sensors", "a comma-separated list of log columns");
      modem.dialog_sensors.push_back(name);
      if (comma == std::string::npos) break;
      from = comma + 1;
    }
    if (modem.dialog_sensors.size() > 16) doc.fail("modem.dialog_sensors", "at most 16 columns");
  }
  return modem;
}

TargetBoard read_board(const TomlDocument& doc, const std::filesystem::path& relative_to) {
  TargetBoard board;
  board.source = doc.source();
  board.name = doc.string("name");
  doc.string_or("description", "");
  board.loop.sched_fifo = doc.boolean_or("loop.sched_fifo", false);
  board.loop.priority = integer_in(doc, "loop.priority", 50);
  board.loop.lock_memory = doc.boolean_or("loop.lock_memory", false);
  board.loop.stats_every_us = static_cast<hal::Micros>(std::llround(number_or(doc, "loop.stats_every_s", 60.0) * 1e6));
  board.actuators_board = board_path(doc, "actuators.board", relative_to);
  if (doc.has("gpio.board")) board.gpio_board = board_path(doc, "gpio.board", relative_to);
  board.gps = read_serial(doc, "gps", 9600, 5.0);
  board.compass = read_serial(doc, "compass", 19200, 3.0);
  board.depth = read_depth(doc);
  if (doc.has("power")) board.power = read_power(doc);
  if (doc.has("modem")) board.modem = read_modem(doc, board.name);
  board.log_directory = doc.string_or("log.directory", board.log_directory.string());
  board.bench = doc.boolean_or("bench", false);
  fw::app::FittedDevices fitted;
  fitted.drop_weight = fitted.leak_detector = board.gpio_board.has_value();
  fitted.power_monitor = board.power.has_value();
  fitted.rudder = hal_linux::load_modbus_board(board.actuators_board).rudder.has_value();
  board.vehicle = fw::app::read_vehicle_setup(doc, fitted);
  const std::string law = doc.string_or("vehicle.heading_law", "compensated");
  const auto heading_law = fw::app::heading_law_from_name(law);
  if (!heading_law) doc.fail("vehicle.heading_law", "must be proportional, slocum or compensated");
  board.mission_options.heading_law = *heading_law;
  const std::string dr = doc.string_or("vehicle.dead_reckoning", board.vehicle.flight_model_dr ? "model" : "assumed");
  if (dr != "assumed" && dr != "model") doc.fail("vehicle.dead_reckoning", "must be assumed or model");
  if (dr == "model" && !board.vehicle.flight_model_dr) {
    doc.fail("vehicle.dead_reckoning", "model needs vehicle.dr_dive_alpha_deg and vehicle.dr_climb_alpha_deg");
  }
  board.mission_options.flight_model_dr = dr == "model";
  doc.reject_unknown_keys();
  return board;
}

}  // namespace

std::vector<config::KeyRange> target_board_limits() {
  std::vector<config::KeyRange> table = limits();
  const auto& vehicle = fw::app::vehicle_setup_limits();
  table.insert(table.end(), vehicle.begin(), vehicle.end());
  return table;
}

TargetBoard load_target_board(const std::filesystem::path& path) {
  return read_board(TomlDocument::load(path), path.parent_path());
}

TargetBoard parse_target_board(const std::string& text, const std::string& source_name,
                               const std::filesystem::path& relative_to) {
  return read_board(TomlDocument::parse(text, source_name), relative_to);
}

}  // namespace glider::target
