// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/modbus_board.hpp"

#include <charconv>
#include <cstdint>
#include <limits>

#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/register_map.hpp"
#include "glider/units.hpp"

namespace glider::hal_linux {
namespace {

using config::TomlDocument;

int integer_in(const TomlDocument& doc, const std::string& key, std::int64_t fallback, std::int64_t lo,
               std::int64_t hi) {
  const std::int64_t value = doc.integer_or(key, fallback);
  if (value < lo || value > hi) {
    doc.fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return static_cast<int>(value);
}

BusConfig read_bus(const TomlDocument& doc) {
  BusConfig bus;
  const std::string transport = doc.string("bus.transport");
  if (transport == "tcp") {
    bus.transport = Transport::kTcp;
  } else if (transport == "rtu") {
    bus.transport = Transport::kRtu;
  } else {
    doc.fail("bus.transport", "expected \"tcp\" or \"rtu\", not \"" + transport + "\"");
  }
  bus.host = doc.string_or("bus.host", bus.host);
  bus.port = integer_in(doc, "bus.port", bus.port, 0, 65535);
  bus.device = doc.string_or("bus.device", bus.device);
  bus.baud = integer_in(doc, "bus.baud", bus.baud, 300, 4'000'000);
  const std::string parity = doc.string_or("bus.parity", "N");
  if (parity != "N" && parity != "E" && parity != "O") doc.fail("bus.parity", "expected \"N\", \"E\" or \"O\"");
  bus.parity = parity[0];
  bus.data_bits = integer_in(doc, "bus.data_bits", bus.data_bits, 5, 8);
  bus.stop_bits = integer_in(doc, "bus.stop_bits", bus.stop_bits, 1, 2);
  const std::string mode = doc.string_or("bus.serial_mode", "rs232");
  if (mode != "rs232" && mode != "rs485") doc.fail("bus.serial_mode", "expected \"rs232\" or \"rs485\"");
  bus.rs485 = mode == "rs485";
  bus.response_timeout_ms = integer_in(doc, "bus.response_timeout_ms", bus.response_timeout_ms, 1, 10'000);
  bus.byte_timeout_ms = integer_in(doc, "bus.byte_timeout_ms", bus.byte_timeout_ms, 1, 1'000);
  bus.retries = integer_in(doc, "bus.retries", bus.retries, 0, 10);
  bus.cycle_period_ms = integer_in(doc, "bus.cycle_period_ms", bus.cycle_period_ms, 1, 3'600'000);
  bus.cycle_budget_ms = integer_in(doc, "bus.cycle_budget_ms", bus.cycle_budget_ms, 1, bus.cycle_period_ms);
  if (bus.cycle_budget_ms < bus.response_timeout_ms) {
    doc.fail("bus.cycle_budget_ms",
             "must allow at least one response timeout (" + std::to_string(bus.response_timeout_ms) + " ms)");
  }
  return bus;
}

AxisConfig read_axis(const TomlDocument& doc, const std::string& name, const std::string& unit) {
  const auto key = [&](const std::string& leaf) { return name + "." + leaf; };
  AxisConfig axis;
  axis.name = name;
  axis.unit = unit;
  axis.slave = integer_in(doc, key("slave"), 1, 1, 247);
  axis.base_address = integer_in(doc, key("base_address"), 0, 0, 65535 - regs::kBlockLength);
  axis.counts_per_unit = doc.number(key("counts_per_unit"));
  if (axis.counts_per_unit <= 0.0) doc.fail(key("counts_per_unit"), "must be positive");
  axis.travel_min = doc.number(key("travel_min_" + unit));
  axis.travel_max = doc.number(key("travel_max_" + unit));
  if (axis.travel_min >= axis.travel_max) doc.fail(key("travel_max_" + unit), "must be above travel_min");
  axis.min = doc.number(key("min_" + unit));
  axis.max = doc.number(key("max_" + unit));
  if (axis.min < axis.travel_min || axis.max > axis.travel_max || axis.min >= axis.max) {
    doc.fail(key("max_" + unit), "command limits must be increasing and inside the travel");
  }
  axis.max_rate = doc.number(key("max_rate_" + unit + "_s"));
  axis.rate = doc.number(key("rate_" + unit + "_s"));
  if (axis.rate <= 0.0 || axis.rate > axis.max_rate) doc.fail(key("rate_" + unit + "_s"), "must be in (0, max_rate]");
  // Everything must fit the 16-bit registers (positions signed, speed unsigned).
  for (const std::string leaf : {"travel_min_", "travel_max_"}) {
    const std::string k = key(leaf) + unit;
    if (!value_to_counts(doc.number(k), axis.counts_per_unit)) {
      doc.fail(k, "does not fit a 16-bit register at this counts_per_unit");
    }
  }
  if (axis.max_rate * axis.counts_per_unit > 65535.0) {
    doc.fail(key("max_rate_" + unit + "_s"), "does not fit a 16-bit register at this counts_per_unit");
  }
  return axis;
}

ModbusBoard read_board(const TomlDocument& doc) {
  ModbusBoard board;
  board.source = doc.source();
  doc.string_or("name", "");
  doc.string_or("description", "");
  board.bus = read_bus(doc);
  board.pump = read_axis(doc, "pump", "cc");
  board.slide = read_axis(doc, "slide", "in");
  if (doc.has("rudder")) board.rudder = read_axis(doc, "rudder", "deg");
  doc.reject_unknown_keys();  // a misspelt key first: it explains what follows
  if (board.pump.slave == board.slide.slave && board.pump.base_address == board.slide.base_address) {
    doc.fail("slide.base_address", "overlaps the pump's registers on the same slave");
  }
  for (const AxisConfig* other : {&board.pump, &board.slide}) {
    if (board.rudder && board.rudder->slave == other->slave && board.rudder->base_address == other->base_address) {
      doc.fail("rudder.base_address", "overlaps the " + other->name + "'s registers on the same slave");
    }
  }
  return board;
}

}  // namespace

ModbusBoard load_modbus_board(const std::filesystem::path& path) { return read_board(TomlDocument::load(path)); }

ModbusBoard parse_modbus_board(const std::string& text, const std::string& source_name) {
  return read_board(TomlDocument::parse(text, source_name));
}

void use_tcp_endpoint(BusConfig& bus, const std::string& host_port) {
  const auto colon = host_port.rfind(':');
  int port = -1;
  if (colon != std::string::npos && colon > 0) {
    const char* first = host_port.data() + colon + 1;
    const char* last = host_port.data() + host_port.size();
    const auto [end, ec] = std::from_chars(first, last, port);
    if (ec != std::errc() || end != last) port = -1;
  }
  if (port < 0 || port > 65535) {
    throw config::ConfigError("--tcp " + host_port + ": expected HOST:PORT (e.g. 127.0.0.1:1502)");
  }
  bus.transport = Transport::kTcp;
  bus.host = host_port.substr(0, colon);
  bus.port = port;
}

void use_rtu_device(BusConfig& bus, const std::string& device) {
  bus.transport = Transport::kRtu;
  bus.device = device;
}

std::string describe(const BusConfig& bus) {
  if (bus.transport == Transport::kTcp) return "tcp " + bus.host + ":" + std::to_string(bus.port);
  return "rtu " + bus.device + " " + std::to_string(bus.baud) + " " + std::to_string(bus.data_bits) + bus.parity +
         std::to_string(bus.stop_bits) + (bus.rs485 ? " rs485" : "");
}

}  // namespace glider::hal_linux
