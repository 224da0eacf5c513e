// SPDX-License-Identifier: Apache-2.0
// The bad-value table: every number key of every file format (mission TOML,
// .mi/.ma arguments, vehicle, environment) is tried with NaN, +-inf,
// +-1e308, 0, -1 and an integer that overflows. A value outside the key's
// published range must be refused with file:line, the key, the value and the
// range; a value inside it is a documented acceptance (the range says so) and
// may still be refused by a check between keys, never crash.
#include <CppUTest/TestHarness.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "bad_value_table.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/config/value_limits.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/vehicle_file.hpp"

using glider::config::ConfigError;
using glider::config::KeyRange;
using glider::config::Range;
namespace mf = glider::fw::mission_file;
using namespace glider::test::bad_values;  // NOLINT(google-build-using-namespace): the table's helpers

namespace {

const std::string kEnvironment =
    "[profile]\n"
    "depth_m = [0.0, 100.0]\n"
    "density_kg_m3 = [1025.0, 1026.0]\n"
    "temperature_c = [12.0, 8.0]\n"
    "current_east_m_s = [0.1, 0.0]\n"
    "current_north_m_s = [0.0, 0.0]\n"
    "vertical_velocity_m_s = [0.0, 0.0]\n";

}  // namespace

TEST_GROUP(ValueLimits){};

TEST(ValueLimits, RangeCheckRefusesNaNInfinityAndOverflow) {
  const Range r{-1.0, 1.0, "m"};
  CHECK(glider::config::within(0.5, r));
  CHECK_FALSE(glider::config::within(std::nan(""), r));
  CHECK_FALSE(glider::config::within(HUGE_VAL, Range{-HUGE_VAL, HUGE_VAL, ""}));
  STRCMP_EQUAL("value -1e+308 is outside the allowed range [-1, 1] m",
               glider::config::range_problem(-1e308, r).c_str());
  CHECK_FALSE(glider::config::whole_number(1e20, 0, 99).has_value());
  CHECK_FALSE(glider::config::whole_number(9.2233720368547758e18, INT64_MIN, INT64_MAX).has_value());
  CHECK_FALSE(glider::config::whole_number(std::nan(""), 0, 99).has_value());
  CHECK_FALSE(glider::config::whole_number(1.5, 0, 99).has_value());
  LONGS_EQUAL(42, *glider::config::whole_number(42.0, 0, 99));
  const std::string huge(10'000'000, 'x');
  CHECK(glider::config::shorten(huge).size() < 100);
}

TEST(ValueLimits, EveryMissionTomlKey) {
  const auto load = [](const std::string& text) {
    glider::fw::read_flight_config(glider::config::TomlDocument::parse(text, "bad.toml"));
  };
  const int cases = try_toml_format(read_text(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"),
                                    glider::fw::flight_config_limits(), load, scalar);
  CHECK(cases >= 22 * 8);
}

TEST(ValueLimits, EveryVehicleKey) {
  const auto load = [](const std::string& text) { glider::model::parse_vehicle_text(text, "bad.toml"); };
  const int cases = try_toml_format(read_text(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml"),
                                    glider::model::vehicle_file_limits(), load, scalar);
  CHECK(cases >= 50 * 8);
}

TEST(ValueLimits, EveryEnvironmentKey) {
  const auto load = [](const std::string& text) { glider::model::parse_environment_text(text, "bad.toml"); };
  // Profile columns are arrays: the bad value is the second element.
  const auto value_text = [](const KeyRange& key, const std::string& bad) {
    const std::string name = key.key;
    if (name.rfind("profile.", 0) != 0) return bad;
    const std::string first = name == "profile.density_kg_m3"        ? "1025.0"
                              : name == "profile.practical_salinity" ? "35.0"
                              : name == "profile.temperature_c"      ? "12.0"
                                                                     : "0.0";
    return "[" + first + ", " + bad + "]";
  };
  std::vector<KeyRange> keys;
  for (const KeyRange& k : glider::model::environment_file_limits()) {
    // Salinity and density exclude each other: salinity is tried on its own below.
    if (std::string(k.key) != "profile.practical_salinity") keys.push_back(k);
  }
  const int cases = try_toml_format(kEnvironment, keys, load, value_text);
  CHECK(cases >= 12 * 8);
  // Without the density column (an empty one is refused, not read as absent).
  int line = 0;
  std::string no_density = set_toml_key(kEnvironment, "profile.density_kg_m3", "[]", line);
  const std::size_t at = no_density.find("density_kg_m3 = []\n");
  CHECK(at != std::string::npos);
  no_density.erase(at, std::string("density_kg_m3 = []\n").size());
  try_toml_format(no_density, {{"profile.practical_salinity", {0.0, 42.0, ""}}}, load, value_text);
}

namespace {

// A mission using every behavior the loader flies, its goto_list waypoints in
// an argument file, written under the test output directory.
const std::filesystem::path kMissionDir = GLIDER_TEST_OUTPUT_DIR "/value_limits_mission";

const char* const kBaseMission =
    "behavior: abend\n"
    "    b_arg: overdepth(m) 60\n"
    "    b_arg: overtime(s) 14400\n"
    "behavior: surface\n"
    "    b_arg: start_when(enum) 1\n"
    "    b_arg: end_action(enum) 1\n"
    "    b_arg: gps_wait_time(s) 120\n"
    "behavior: goto_list\n"
    "    b_arg: args_from_file(enum) 10\n"
    "    b_arg: start_when(enum) 0\n"
    "behavior: set_heading\n"
    "    b_arg: use_heading(enum) 2\n"
    "    b_arg: heading_value(X) 0.0\n"
    "behavior: prepare_to_dive\n"
    "    b_arg: start_when(enum) 0\n"
    "    b_arg: wait_time(s) 720\n"
    "behavior: yo\n"
    "    b_arg: num_half_cycles_to_do(nodim) 4\n"
    "    b_arg: d_target_depth(m) 40\n"
    "    b_arg: d_use_pitch(enum) 3\n"
    "    b_arg: d_pitch_value(X) -0.4363\n"
    "    b_arg: d_bpump_value(X) -1000\n"
    "    b_arg: c_target_depth(m) 5\n"
    "    b_arg: c_use_pitch(enum) 3\n"
    "    b_arg: c_pitch_value(X) 0.4363\n"
    "    b_arg: c_bpump_value(X) 1000\n"
    "behavior: dive_to\n"
    "    b_arg: target_depth(m) 30\n";

const char* const kGotoArgs =
    "behavior_name=goto_list\n"
    "<start:b_arg>\n"
    "    b_arg: num_legs_to_run(nodim) -1\n"
    "    b_arg: initial_wpt(enum) -1\n"
    "    b_arg: num_waypoints(nodim) 2\n"
    "<end:b_arg>\n"
    "<start:waypoints>\n"
    "-7040.0 4140.0\n"
    "-7041.0 4141.0\n"
    "<end:waypoints>\n";

void write_mission_files(const std::string& goto_args) {
  std::filesystem::create_directories(kMissionDir / "mafiles");
  std::ofstream(kMissionDir / "mafiles" / "goto_l10.ma") << goto_args;
}

mf::LoadedMission load_mi(const std::string& text) {
  mf::MissionVehicle vehicle;
  return mf::load_mission(mf::parse_mi_text(text, "bad.mi", kMissionDir), vehicle, glider::fw::FlightSoftwareConfig{});
}

// The first error diagnostic's text, or "".
std::string first_error(const mf::LoadedMission& loaded) {
  for (const mf::Diagnostic& d : loaded.diagnostics) {
    if (d.severity == mf::Severity::kError) return d.text();
  }
  return "";
}

}  // namespace

TEST(ValueLimits, EveryMissionArgument) {
  write_mission_files(kGotoArgs);
  const mf::LoadedMission base = load_mi(kBaseMission);
  CHECK_TEXT(base.config.has_value(), first_error(base).c_str());
  int cases = 0;
  for (const mf::ArgumentRange& arg : mf::mission_argument_limits()) {
    for (const std::string& bad : kBadValues) {
      ++cases;
      // The argument right after its behavior's header line.
      std::vector<std::string> lines = split_lines(kBaseMission);
      std::size_t header = 0;
      while (header < lines.size() && lines[header] != "behavior: " + arg.behavior) ++header;
      CHECK_TEXT(header < lines.size(), arg.behavior.c_str());
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(header) + 1,
                   "    b_arg: " + arg.argument + "(X) " + bad);
      const int line = static_cast<int>(header) + 2;
      const mf::LoadedMission loaded = load_mi(join_lines(lines));
      const double value = std::strtod(bad.c_str(), nullptr);
      if (glider::config::within(value, arg.range)) continue;  // documented acceptance (or a later check)
      const std::string what = arg.behavior + " " + arg.argument + " " + bad;
      CHECK_TEXT(!loaded.config.has_value(), ("accepted " + what).c_str());
      bool named = false;
      for (const mf::Diagnostic& d : loaded.diagnostics) {
        const std::string text = d.text();
        named = named || (d.severity == mf::Severity::kError && d.line == line && contains(text, "bad.mi:") &&
                          contains(text, arg.argument));
      }
      CHECK_TEXT(named, (what + ": " + first_error(loaded)).c_str());
    }
  }
  CHECK(cases >= 30 * 8);
}

TEST(ValueLimits, NaNWaypointsAreRefusedWithTheirLine) {
  write_mission_files(
      "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 2\n<end:b_arg>\n"
      "<start:waypoints>\n-7040.0 4140.0\nnan nan\n<end:waypoints>\n");
  const mf::LoadedMission loaded = load_mi(kBaseMission);
  CHECK_FALSE(loaded.config.has_value());
  STRCMP_CONTAINS("goto_l10.ma:7: error: waypoint", first_error(loaded).c_str());
  write_mission_files(kGotoArgs);
}

TEST(ValueLimits, ArgumentFileNumberThatOverflowsIsRefused) {
  write_mission_files(kGotoArgs);
  std::string text = kBaseMission;
  text.replace(text.find("args_from_file(enum) 10"), 23, std::string("args_from_file(enum) ") + kOverflow);
  const mf::LoadedMission loaded = load_mi(text);
  CHECK_FALSE(loaded.config.has_value());
  STRCMP_CONTAINS("bad.mi:9: error: args_from_file: value 1e+20 is outside the allowed range [0, 99]",
                  first_error(loaded).c_str());
}

TEST(ValueLimits, HugeFieldIsShortenedInTheMessage) {
  const std::string huge(10'000'000, '7');
  std::string text = kBaseMission;
  text.replace(text.find("overtime(s) 14400"), 17, "overtime(s) x" + huge);
  const std::string error = first_error(load_mi(text));
  STRCMP_CONTAINS("bad.mi:3: error: value of overtime is not a finite number", error.c_str());
  CHECK(error.size() < 300);
}

TEST(ValueLimits, IssueCasesNameFileLineKeyValueAndRange) {
  const std::string mission = read_text(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml");
  const auto toml_error = [](const std::string& text) -> std::string {
    try {
      glider::fw::read_flight_config(glider::config::TomlDocument::parse(text, "bad.toml"));
    } catch (const ConfigError& error) {
      return error.what();
    }
    return "";
  };
  int line = 0;
  STRCMP_CONTAINS("mission.dive_pitch_deg: value -1e+308 is outside the allowed range [-80, 80] deg",
                  toml_error(set_toml_key(mission, "mission.dive_pitch_deg", "-1e308", line)).c_str());
  // set_toml_key sets `line`: call it before the line is used (the order in
  // which function arguments are evaluated differs between compilers and targets).
  const std::string surfaced_error = toml_error(set_toml_key(mission, "mission.surfaced_depth_m", "-3.0", line));
  STRCMP_CONTAINS(("bad.toml:" + std::to_string(line) + ":").c_str(), surfaced_error.c_str());
  std::string vehicle = read_text(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  try {
    glider::model::parse_vehicle_text(set_toml_key(vehicle, "hydrodynamics.cd0", "1e308", line), "bad.toml");
    FAIL("cd0 1e308 accepted");
  } catch (const ConfigError& error) {
    STRCMP_CONTAINS(("bad.toml:" + std::to_string(line) + ":").c_str(), error.what());
    STRCMP_CONTAINS("hydrodynamics.cd0: value 1e+308 is outside the allowed range [0.001, 10]", error.what());
  }
}
