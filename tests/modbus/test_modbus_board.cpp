// SPDX-License-Identifier: Apache-2.0
// Modbus board files: the default one reads, malformed ones are refused with
// file, line and problem.
#include <CppUTest/TestHarness.h>

#include "../unit/config_error.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/hal_linux/modbus_board.hpp"

using namespace glider;

namespace {

const char* const kValid = R"(
[bus]
transport = "rtu"
device = "/dev/ttyS1"
[pump]
counts_per_unit = 10
travel_min_cc = -270.0
travel_max_cc = 270.0
min_cc = -250.0
max_cc = 250.0
rate_cc_s = 30.0
max_rate_cc_s = 45.0
[slide]
base_address = 32
counts_per_unit = 1000
travel_min_in = -1.2
travel_max_in = 1.2
min_in = -1.0
max_in = 1.0
rate_in_s = 0.05
max_rate_in_s = 0.1
)";

std::string error_of(const std::string& text) {
  return test::config_error_of([&] { hal_linux::parse_modbus_board(text, "board.toml"); });
}

using test::replaced;

}  // namespace

TEST_GROUP(ModbusBoardFile){};

TEST(ModbusBoardFile, TheDefaultBoardReads) {
  const auto board = hal_linux::load_modbus_board(GLIDER_SOURCE_DIR "/boards/actuators/default_modbus.toml");
  CHECK(board.bus.transport == hal_linux::Transport::kTcp);
  CHECK_EQUAL(32, board.slide.base_address);
  DOUBLES_EQUAL(30.0, board.pump.rate, 0.0);
  STRCMP_EQUAL("rtu /dev/ttyS1 19200 8N1", hal_linux::describe(hal_linux::parse_modbus_board(kValid, "b").bus).c_str());
}

TEST(ModbusBoardFile, ProblemsNameFileLineAndKey) {
  STRCMP_EQUAL("board.toml:3:13: bus.transport: expected \"tcp\" or \"rtu\", not \"can\"",
               error_of(replaced(kValid, "\"rtu\"", "\"can\"")).c_str());
  STRCMP_EQUAL(
      "board.toml:10:10: pump.max_cc: command limits [-250, 300] must be increasing and inside the travel [-270, 270]",
      error_of(replaced(kValid, "max_cc = 250.0", "max_cc = 300.0")).c_str());
  STRCMP_EQUAL("board.toml:14:15: unknown key 'slide.base_adress'",
               error_of(replaced(kValid, "base_address", "base_adress")).c_str());
  STRCMP_EQUAL(
      "board.toml:16:17: slide.travel_min_in: value -40 does not fit a 16-bit register at counts_per_unit 1000",
      error_of(replaced(kValid, "travel_min_in = -1.2", "travel_min_in = -40.0")).c_str());
  CHECK(error_of(replaced(kValid, "[slide]\nbase_address = 32", "[slide]")).find("overlaps") != std::string::npos);
  STRCMP_EQUAL("board.toml: missing required key 'pump.rate_cc_s'",
               error_of(replaced(kValid, "rate_cc_s = 30.0", "")).c_str());
}

TEST(ModbusBoardFile, EndpointOverrides) {
  hal_linux::BusConfig bus;
  hal_linux::use_tcp_endpoint(bus, "10.0.0.7:502");
  STRCMP_EQUAL("tcp 10.0.0.7:502", hal_linux::describe(bus).c_str());
  CHECK_THROWS(config::ConfigError, hal_linux::use_tcp_endpoint(bus, "10.0.0.7"));
  CHECK_THROWS(config::ConfigError, hal_linux::use_tcp_endpoint(bus, "host:99999"));
}

TEST(ModbusBoardFile, AnOptionalRudderAxis) {
  CHECK_FALSE(hal_linux::parse_modbus_board(kValid, "b").rudder.has_value());
  const std::string rudder =
      "[rudder]\nslave = 2\ncounts_per_unit = 10\ntravel_min_deg = -30.0\n"
      "travel_max_deg = 30.0\nmin_deg = -25.0\nmax_deg = 25.0\nrate_deg_s = 10.0\n"
      "max_rate_deg_s = 20.0\n";
  const auto board = hal_linux::parse_modbus_board(kValid + rudder, "b");
  CHECK_TRUE(board.rudder.has_value());
  STRCMP_EQUAL("deg", board.rudder->unit.c_str());
  DOUBLES_EQUAL(25.0, board.rudder->max, 0.0);
  STRCMP_CONTAINS("rudder.base_address: value 0 overlaps the pump's registers on the same slave 1",
                  error_of(kValid + replaced(rudder, "slave = 2", "slave = 1")).c_str());
}
