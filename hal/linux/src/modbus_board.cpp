// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/modbus_board.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <deque>
#include <limits>
#include <utility>

#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/register_map.hpp"
#include "glider/units.hpp"

namespace glider::hal_linux {
namespace {

using config::TomlDocument;

using config::Range;

// The axes and the units of their numbers.
constexpr std::array<std::pair<const char*, const char*>, 3> kAxes{
    {{"pump", "cc"}, {"slide", "in"}, {"rudder", "deg"}}};

// Every number of the board file and its range (value_limits.hpp). Travel and
// command limits: finite and far beyond any glider's; their order and the
// 16-bit registers are checked after (read_axis).
const std::vector<config::KeyRange>& limits() {
  static const std::vector<config::KeyRange> table = [] {
    std::vector<config::KeyRange> t{
        {"bus.port", {0.0, 65535.0, ""}},
        {"bus.baud", {300.0, 4'000'000.0, "baud"}},
        {"bus.data_bits", {5.0, 8.0, ""}},
        {"bus.stop_bits", {1.0, 2.0, ""}},
        {"bus.response_timeout_ms", {1.0, 10'000.0, "ms"}},
        {"bus.byte_timeout_ms", {1.0, 1'000.0, "ms"}},
        {"bus.retries", {0.0, 10.0, ""}},
        {"bus.cycle_period_ms", {1.0, 3'600'000.0, "ms"}},
        {"bus.cycle_budget_ms", {1.0, 3'600'000.0, "ms (and at most bus.cycle_period_ms)"}},
    };
    // The table holds the key names' characters: a deque never moves them.
    static std::deque<std::string> names;
    for (const auto& [axis, unit] : kAxes) {
      const std::string a = axis;
      const std::string u = unit;
      const auto add = [&](const std::string& leaf, Range range) {
        names.push_back(a);
        names.back().append(".").append(leaf);
        t.push_back({names.back().c_str(), range});
      };
      add("slave", {1.0, 247.0, ""});
      add("base_address", {0.0, 65535.0 - static_cast<double>(regs::kBlockLength), ""});
      add("counts_per_unit", {1e-3, 1e6, "counts per unit"});
      for (const char* leaf : {"travel_min_", "travel_max_", "min_", "max_"}) add(leaf + u, {-1e4, 1e4, unit});
      add("max_rate_" + u + "_s", {1e-6, 1e4, "unit/s"});
      add("rate_" + u + "_s", {1e-6, 1e4, "unit/s (and at most max_rate)"});
    }
    return t;
  }();
  return table;
}

double number(const TomlDocument& doc, const std::string& key) {
  return doc.number(key, config::range_of(limits(), key));
}

// An integer key of the table: a whole number in its range.
int integer_in(const TomlDocument& doc, const std::string& key, std::int64_t fallback) {
  const Range& range = config::range_of(limits(), key);
  return static_cast<int>(
      doc.integer_or(key, fallback, static_cast<std::int64_t>(range.min), static_cast<std::int64_t>(range.max)));
}

// libmodbus connects to (and the simulator binds) a numeric IPv4 address;
// a name would need a lookup in flight, and inet_addr("no-such-host") is
// INADDR_NONE, 255.255.255.255.
bool numeric_ipv4(const std::string& host) {
  in_addr address{};
  return inet_pton(AF_INET, host.c_str(), &address) == 1;
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
  if (!numeric_ipv4(bus.host)) {
    doc.fail("bus.host", "value \"" + config::shorten(bus.host) +
                             "\" is not a numeric IPv4 address (e.g. 127.0.0.1; no name lookups in flight)");
  }
  bus.port = integer_in(doc, "bus.port", bus.port);
  bus.device = doc.string_or("bus.device", bus.device);
  bus.baud = integer_in(doc, "bus.baud", bus.baud);
  const std::string parity = doc.string_or("bus.parity", "N");
  if (parity != "N" && parity != "E" && parity != "O") doc.fail("bus.parity", "expected \"N\", \"E\" or \"O\"");
  bus.parity = parity[0];
  bus.data_bits = integer_in(doc, "bus.data_bits", bus.data_bits);
  bus.stop_bits = integer_in(doc, "bus.stop_bits", bus.stop_bits);
  const std::string mode = doc.string_or("bus.serial_mode", "rs232");
  if (mode != "rs232" && mode != "rs485") doc.fail("bus.serial_mode", "expected \"rs232\" or \"rs485\"");
  bus.rs485 = mode == "rs485";
  bus.response_timeout_ms = integer_in(doc, "bus.response_timeout_ms", bus.response_timeout_ms);
  bus.byte_timeout_ms = integer_in(doc, "bus.byte_timeout_ms", bus.byte_timeout_ms);
  bus.retries = integer_in(doc, "bus.retries", bus.retries);
  bus.cycle_period_ms = integer_in(doc, "bus.cycle_period_ms", bus.cycle_period_ms);
  bus.cycle_budget_ms = integer_in(doc, "bus.cycle_budget_ms", bus.cycle_budget_ms);
  if (bus.cycle_budget_ms > bus.cycle_period_ms) {
    doc.fail("bus.cycle_budget_ms", "value " + std::to_string(bus.cycle_budget_ms) +
                                        " is longer than the cycle (bus.cycle_period_ms " +
                                        std::to_string(bus.cycle_period_ms) + " ms)");
  }
  if (bus.cycle_budget_ms < bus.response_timeout_ms) {
    doc.fail("bus.cycle_budget_ms", "value " + std::to_string(bus.cycle_budget_ms) +
                                        " must allow at least one response timeout (" +
                                        std::to_string(bus.response_timeout_ms) + " ms)");
  }
  return bus;
}

AxisConfig read_axis(const TomlDocument& doc, const std::string& name, const std::string& unit) {
  const auto key = [&](const std::string& leaf) { return name + "." + leaf; };
  AxisConfig axis;
  axis.name = name;
  axis.unit = unit;
  axis.slave = integer_in(doc, key("slave"), 1);
  axis.base_address = integer_in(doc, key("base_address"), 0);
  axis.counts_per_unit = number(doc, key("counts_per_unit"));
  axis.travel_min = number(doc, key("travel_min_" + unit));
  axis.travel_max = number(doc, key("travel_max_" + unit));
  const auto show = [](double v) { return config::show_value(v); };
  if (axis.travel_min >= axis.travel_max) {
    doc.fail(key("travel_max_" + unit), "value " + show(axis.travel_max) + " must be above travel_min_" + unit + " (" +
                                            show(axis.travel_min) + ")");
  }
  axis.min = number(doc, key("min_" + unit));
  axis.max = number(doc, key("max_" + unit));
  if (axis.min < axis.travel_min || axis.max > axis.travel_max || axis.min >= axis.max) {
    doc.fail(key("max_" + unit), "command limits [" + show(axis.min) + ", " + show(axis.max) +
                                     "] must be increasing and inside the travel [" + show(axis.travel_min) + ", " +
                                     show(axis.travel_max) + "]");
  }
  axis.max_rate = number(doc, key("max_rate_" + unit + "_s"));
  axis.rate = number(doc, key("rate_" + unit + "_s"));
  if (axis.rate > axis.max_rate) {
    doc.fail(key("rate_" + unit + "_s"),
             "value " + show(axis.rate) + " is above max_rate_" + unit + "_s (" + show(axis.max_rate) + ")");
  }
  // Everything must fit the 16-bit registers (positions signed, speed unsigned).
  for (const double travel : {axis.travel_min, axis.travel_max}) {
    if (!value_to_counts(travel, axis.counts_per_unit)) {
      doc.fail(
          key((travel == axis.travel_min ? "travel_min_" : "travel_max_") + unit),
          "value " + show(travel) + " does not fit a 16-bit register at counts_per_unit " + show(axis.counts_per_unit));
    }
  }
  if (axis.max_rate * axis.counts_per_unit > 65535.0) {
    doc.fail(key("max_rate_" + unit + "_s"), "value " + show(axis.max_rate) +
                                                 " does not fit a 16-bit register at counts_per_unit " +
                                                 show(axis.counts_per_unit));
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
    doc.fail("slide.base_address", "value " + std::to_string(board.slide.base_address) +
                                       " overlaps the pump's registers on the same slave " +
                                       std::to_string(board.slide.slave));
  }
  for (const AxisConfig* other : {&board.pump, &board.slide}) {
    if (board.rudder && board.rudder->slave == other->slave && board.rudder->base_address == other->base_address) {
      doc.fail("rudder.base_address", "value " + std::to_string(board.rudder->base_address) + " overlaps the " +
                                          other->name + "'s registers on the same slave " +
                                          std::to_string(other->slave));
    }
  }
  return board;
}

}  // namespace

const std::vector<config::KeyRange>& modbus_board_limits() { return limits(); }

ModbusBoard load_modbus_board(const std::filesystem::path& path) { return read_board(TomlDocument::load(path)); }

ModbusBoard parse_modbus_board(const std::string& text, const std::string& source_name) {
  return read_board(TomlDocument::parse(text, source_name));
}

std::string tcp_endpoint_problem(const std::string& host_port) {
  const auto colon = host_port.rfind(':');
  int port = -1;
  if (colon != std::string::npos && colon > 0) {
    const char* first = host_port.data() + colon + 1;
    const char* last = host_port.data() + host_port.size();
    const auto [end, ec] = std::from_chars(first, last, port);
    if (ec != std::errc() || end != last) port = -1;
  }
  if (port < 0 || port > 65535) {
    return "value " + config::shorten(host_port) + " is not HOST:PORT with a port in [0, 65535] (e.g. 127.0.0.1:1502)";
  }
  const std::string host = host_port.substr(0, colon);
  if (!numeric_ipv4(host)) {
    return "value " + config::shorten(host_port) + ": host \"" + config::shorten(host) +
           "\" is not a numeric IPv4 address (e.g. 127.0.0.1)";
  }
  return "";
}

void use_tcp_endpoint(BusConfig& bus, const std::string& host_port) {
  if (const std::string problem = tcp_endpoint_problem(host_port); !problem.empty()) {
    throw config::ConfigError("--tcp " + problem);
  }
  const auto colon = host_port.rfind(':');
  bus.transport = Transport::kTcp;
  bus.host = host_port.substr(0, colon);
  bus.port = std::stoi(host_port.substr(colon + 1));
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
