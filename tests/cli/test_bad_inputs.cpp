// SPDX-License-Identifier: Apache-2.0
// Bad values outside the command lines' option table (check_numeric_options.py):
// the board files' keys in the bad-value table (as missions, vehicles and
// environments are in tests/unit/test_value_limits.cpp), and the probe's
// findings that are file contents or option texts rather than numbers.
#include <CppUTest/TestHarness.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "../unit/bad_value_table.hpp"
#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/firmware/mission_file/mi_document.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/sil/fault_injection.hpp"
#include "glider/target/target_board.hpp"

using namespace glider::test::bad_values;  // NOLINT(google-build-using-namespace): the table's helpers
using glider::config::ConfigError;
using glider::config::KeyRange;

namespace {

std::string error_of(const std::function<void()>& load) {
  try {
    load();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_GROUP(BoardLimits){};

TEST(BoardLimits, EveryActuatorBoardKey) {
  const auto load = [](const std::string& text) { glider::hal_linux::parse_modbus_board(text, "bad.toml"); };
  const int cases = try_toml_format(read_text(GLIDER_SOURCE_DIR "/boards/actuators/three_axis_modbus.toml"),
                                    glider::hal_linux::modbus_board_limits(), load, scalar);
  CHECK(cases >= 36 * 8);  // 9 bus keys, 9 per axis
}

TEST(BoardLimits, EveryTargetBoardKey) {
  const std::filesystem::path target = GLIDER_SOURCE_DIR "/boards/target";
  const auto load = [&target](const std::string& text) {
    glider::target::parse_target_board(text, "bad.toml", target);
  };
  std::vector<KeyRange> keys;
  for (const KeyRange& k : glider::target::target_board_limits()) {
    // Read only with the flight-model dead reckoning's angle tables (a board without them leaves it unread).
    if (std::string(k.key) != "vehicle.dr_coast_time_constant_s") keys.push_back(k);
  }
  // With a [modem] (comms): its baud is a key of the table too.
  const std::string board = read_text(GLIDER_SOURCE_DIR "/boards/target/cm4_glider.toml") +
                            "\n[modem]\ndevice = \"/dev/ttyAMA4\"\nbaud = 19200\nprimary_number = \"0088160000000\"\n";
  const int cases = try_toml_format(board, keys, load, scalar);
  CHECK(cases >= 27 * 8);
}

TEST(BoardLimits, BetweenKeyRefusalsNameTheValue) {
  const std::string board = read_text(GLIDER_SOURCE_DIR "/boards/actuators/three_axis_modbus.toml");
  int line = 0;
  STRCMP_CONTAINS("pump.max_cc: command limits [-250, 300] must be increasing and inside the travel [-270, 270]",
                  error_of([&] {
                    glider::hal_linux::parse_modbus_board(set_toml_key(board, "pump.max_cc", "300.0", line), "b");
                  }).c_str());
  STRCMP_CONTAINS("bus.cycle_budget_ms: value 2000 is longer than the cycle (bus.cycle_period_ms 1000 ms)",
                  error_of([&] {
                    glider::hal_linux::parse_modbus_board(set_toml_key(board, "bus.cycle_budget_ms", "2000", line),
                                                          "b");
                  }).c_str());
}

TEST(BoardLimits, NonNumericHostIsRefused) {
  const std::string board = read_text(GLIDER_SOURCE_DIR "/boards/actuators/three_axis_modbus.toml");
  int line = 0;
  const std::string error = error_of([&] {
    glider::hal_linux::parse_modbus_board(set_toml_key(board, "bus.host", "\"no-such-host\"", line), "bad.toml");
  });
  STRCMP_CONTAINS(("bad.toml:" + std::to_string(line) + ":").c_str(), error.c_str());
  STRCMP_CONTAINS("bus.host: value \"no-such-host\" is not a numeric IPv4 address", error.c_str());
  glider::hal_linux::BusConfig bus;
  STRCMP_CONTAINS("host \"no-such-host\" is not a numeric IPv4 address",
                  error_of([&] { glider::hal_linux::use_tcp_endpoint(bus, "no-such-host:1502"); }).c_str());
  glider::hal_linux::use_tcp_endpoint(bus, "127.0.0.1:1502");
  STRCMP_EQUAL("127.0.0.1", bus.host.c_str());
}

TEST_GROUP(FileProbes){};

TEST(FileProbes, UnknownFittedKeyIsRefused) {
  const std::string text = "[fitted]\nrudder = true\nruder = false\n";
  const std::string error = error_of(
      [&] { glider::fw::app::read_fitted_devices(glider::config::TomlDocument::parse(text, "vehicle.toml"), {}); });
  STRCMP_CONTAINS("vehicle.toml:3:9: unknown key 'fitted.ruder'", error.c_str());
  const auto fitted = glider::fw::app::read_fitted_devices(
      glider::config::TomlDocument::parse("[fitted]\nrudder = false\n", "vehicle.toml"), {});
  CHECK_FALSE(fitted.rudder);
}

TEST(FileProbes, SurfacedDepthZeroIsRefusedWithRangeAndWhy) {
  const std::string mission = read_text(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml");
  int line = 0;
  const std::string text = set_toml_key(mission, "mission.surfaced_depth_m", "0", line);
  const std::string error =
      error_of([&] { glider::fw::read_flight_config(glider::config::TomlDocument::parse(text, "bad.toml")); });
  STRCMP_CONTAINS(("bad.toml:" + std::to_string(line) + ":").c_str(), error.c_str());
  STRCMP_CONTAINS("mission.surfaced_depth_m: value 0 is outside the allowed range [0.3, 10] m", error.c_str());
  STRCMP_CONTAINS("never reads 0 at the surface", error.c_str());
}

TEST(FileProbes, FifoIsNotAMission) {
  const std::filesystem::path dir = GLIDER_TEST_OUTPUT_DIR "/cli_fifo";
  std::filesystem::create_directories(dir);
  for (const char* name : {"mission.mi", "mission.toml"}) {
    const std::filesystem::path fifo = dir / name;
    std::filesystem::remove(fifo);
    CHECK_EQUAL(0, mkfifo(fifo.c_str(), 0600));
  }
  // Would block in the open() forever before: nobody writes the FIFO.
  const auto mi = glider::fw::mission_file::read_mi_file(dir / "mission.mi");
  CHECK_FALSE(mi.diagnostics.empty());
  STRCMP_CONTAINS("not a regular file", mi.diagnostics.front().message.c_str());
  STRCMP_CONTAINS("not a regular file",
                  error_of([&] { glider::config::TomlDocument::load(dir / "mission.toml"); }).c_str());
}

TEST(FileProbes, FaultTimesAreFiniteAndWithinSixtyDays) {
  std::string error;
  for (const char* bad : {"leak@inf", "leak@infs", "leak@nan", "leak@1e308h", "leak@-1", "leak@61d", "leak@1441h"}) {
    error.clear();
    CHECK_FALSE_TEXT(glider::sil::parse_fault(bad, error).has_value(), bad);
    STRCMP_CONTAINS("in [0, 5184000] s", error.c_str());
  }
  const auto fault = glider::sil::parse_fault("leak@1440h", error);
  CHECK_TRUE(fault.has_value());
  DOUBLES_EQUAL(5184000.0, fault->at_s, 0.0);
}

TEST(FileProbes, ArgumentFileFromMemory) {
  namespace mf = glider::fw::mission_file;
  const std::string good = read_text(GLIDER_SOURCE_DIR "/boards/missions/box_current/mafiles/goto_l10.ma");
  const mf::MiDocument doc = mf::parse_ma_text(good, "goto_l10.ma", "goto_list");
  CHECK_FALSE_TEXT(doc.has_errors(), doc.diagnostics.empty() ? "" : doc.diagnostics.front().text().c_str());
  CHECK_TRUE(doc.behaviors.front().has_waypoint_section);
  CHECK_FALSE(doc.behaviors.front().waypoints.empty());
  const mf::MiDocument bad = mf::parse_ma_text(
      "behavior_name=goto_list\n<start:waypoints>\n-7040.0 4140.0\nnan nan\n<end:waypoints>\n", "bad.ma", "goto_list");
  CHECK_TRUE(bad.has_errors());
  STRCMP_CONTAINS("bad.ma:4: error: waypoint must be 'lon lat' (finite numbers)",
                  bad.diagnostics.front().text().c_str());
}
