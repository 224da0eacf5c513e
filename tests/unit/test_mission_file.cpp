// SPDX-License-Identifier: Apache-2.0
// Slocum mission files: the real comet-nsb3 mission loads; malformed and
// unsafe missions are refused with file:line, before launch.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "glider/firmware/mission_file/mission_loader.hpp"

using namespace glider;
using fw::mission_file::LoadedMission;
using fw::mission_file::MissionVehicle;
using fw::mission_file::Severity;

namespace {

MissionVehicle comet() {
  MissionVehicle v;
  v.max_working_depth_m = 102.0;
  v.limits.ballast_min_cc = -230.0;
  v.limits.ballast_max_cc = 230.0;
  v.limits.battery_min_in = -0.595;
  v.limits.battery_max_in = 1.405;
  return v;
}

std::string all_text(const LoadedMission& m) {
  std::string out;
  for (const auto& d : m.diagnostics) out += d.text() + "\n";
  return out;
}

// A mission directory in the test output: missions/NAME.mi and mafiles/.
struct MissionDir {
  std::filesystem::path root;
  explicit MissionDir(const std::string& name) : root(std::filesystem::path(GLIDER_TEST_OUTPUT_DIR) / "mi" / name) {
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root / "missions");
    std::filesystem::create_directories(root / "mafiles");
  }
  void ma(const std::string& file, const std::string& text) const { std::ofstream(root / "mafiles" / file) << text; }
  LoadedMission load(const std::string& mi) const {
    std::ofstream(root / "missions" / "m.mi") << mi;
    return fw::mission_file::load_mission_file(root / "missions" / "m.mi", comet());
  }
};

const char* kAbend =
    "behavior: abend\n"
    "  b_arg: overdepth(m) 60\n"
    "  b_arg: overtime(s) 7200\n";
const char* kYo =
    "behavior: yo\n"
    "  b_arg: num_half_cycles_to_do(nodim) 4\n"
    "  b_arg: d_target_depth(m) 40\n"
    "  b_arg: c_target_depth(m) 5\n"
    "  b_arg: d_use_pitch(enum) 3\n"
    "  b_arg: d_pitch_value(X) -0.45\n"
    "  b_arg: c_use_pitch(enum) 3\n"
    "  b_arg: c_pitch_value(X) 0.45\n";

}  // namespace

TEST_GROUP(MissionFile){};

TEST(MissionFile, TheRealCometNsb3MissionLoads) {
  const LoadedMission m =
      fw::mission_file::load_mission_file(GLIDER_SOURCE_DIR "/boards/missions/comet-nsb3/missions/nsb3.mi", comet());
  CHECK_TEXT(m.config.has_value(), all_text(m).c_str());
  const fw::FlightSoftwareConfig& c = *m.config;
  LONGS_EQUAL(2, c.plan.waypoint_count);
  DOUBLES_EQUAL(54.0 + 33.5 / 60.0, c.plan.waypoints[0].lat_deg, 1e-9);  // 713.000 5433.500: lon first
  DOUBLES_EQUAL(7.0 + 13.0 / 60.0, c.plan.waypoints[0].lon_deg, 1e-9);
  DOUBLES_EQUAL(54.3, c.plan.waypoints[1].lat_deg, 1e-9);
  DOUBLES_EQUAL(500.0, c.plan.waypoint_radius_m, 0.0);
  LONGS_EQUAL(fw::kLegsLoopForever, c.plan.legs_to_run);
  DOUBLES_EQUAL(10800.0, c.plan.surface_interval_s, 0.0);  // surfac10: every 3 h, before the 12 h no-comm net
  DOUBLES_EQUAL(300.0, c.plan.gps_wait_s, 0.0);
  DOUBLES_EQUAL(300.0, c.plan.surface_dwell_s, 0.0);  // end_action 1: keystroke_wait_time
  CHECK_TRUE(c.plan.current_correction);
  DOUBLES_EQUAL(50.0, c.mission.dive_to_m, 0.0);
  DOUBLES_EQUAL(3.0, c.mission.climb_to_m, 0.0);
  DOUBLES_EQUAL(-230.0, c.mission.dive_ballast_cc, 0.0);  // -1000: as far as the pump goes
  DOUBLES_EQUAL(230.0, c.mission.climb_ballast_cc, 0.0);
  DOUBLES_EQUAL(0.405, c.mission.dive_battpos_in, 0.0);  // pump-only pitch
  DOUBLES_EQUAL(0.405, c.mission.climb_battpos_in, 0.0);
  DOUBLES_EQUAL(102.0, c.mission.max_depth_m, 0.0);  // no abend overdepth: the rating
  CHECK_TRUE(std::isinf(c.mission.max_duration_s));  // overtime -1
  DOUBLES_EQUAL(600.0, c.aborts.samedepth_for_s, 0.0);
  DOUBLES_EQUAL(300000.0, c.aborts.max_wpt_distance_m, 0.0);
  CHECK_FALSE(c.aborts.stalled_for_s > 0.0);
  CHECK_FALSE(c.mission.start_at_launch);
  const std::string text = all_text(m);
  CHECK_TEXT(text.find("yo10.ma:7: warning: yo d_target_altitude ignored: no altimeter") != std::string::npos,
             text.c_str());
  CHECK(text.find("nsb3.mi:75: warning: behavior sample") != std::string::npos);
  CHECK(text.find("error") == std::string::npos);
}

TEST(MissionFile, AMinimalYoMissionLoads) {
  const LoadedMission m = MissionDir("minimal").load(std::string(kAbend) + kYo);
  CHECK_TEXT(m.config.has_value(), all_text(m).c_str());
  LONGS_EQUAL(2, m.config->mission.yos);
  DOUBLES_EQUAL(-0.45, m.config->mission.dive_pitch_rad, 0.0);
  CHECK_TRUE(std::isnan(m.config->mission.dive_battpos_in));
  DOUBLES_EQUAL(60.0, m.config->mission.max_depth_m, 0.0);
  DOUBLES_EQUAL(7200.0, m.config->mission.max_duration_s, 0.0);
}

namespace {

// The first error of a loaded mission, "" if it loads.
std::string first_error(const LoadedMission& m) {
  if (m.config) return "";
  for (const auto& d : m.diagnostics) {
    if (d.severity == Severity::kError) return d.text();
  }
  return "refused without an error";
}

// In a fresh mission directory of its own, or in `dir` (with its .ma files).
std::string refusal(const std::string& name, const std::string& mi) { return first_error(MissionDir(name).load(mi)); }
std::string refusal(const MissionDir& dir, const std::string& mi) { return first_error(dir.load(mi)); }

}  // namespace

TEST(MissionFile, SyntaxErrorsNameFileAndLine) {
  STRCMP_EQUAL("m.mi:2: error: expected 'name(unit) value', got 'overdepth 60'",
               refusal("syntax1", "behavior: abend\n  b_arg: overdepth 60\n").c_str());
  STRCMP_EQUAL("m.mi:3: error: value of overtime is not a finite number: 'ten'",
               refusal("syntax2", "behavior: abend\n# comment\n  b_arg: overtime(s) ten\n").c_str());
  STRCMP_EQUAL("m.mi:1: error: b_arg outside a behavior block", refusal("syntax3", "b_arg: overtime(s) 10\n").c_str());
  STRCMP_EQUAL("m.mi:1: error: expected 'behavior:', 'b_arg:' or 'sensor:', got 'hello world'",
               refusal("syntax4", "hello world\n").c_str());
}

TEST(MissionFile, ArgumentFileProblemsNameTheirOwnLine) {
  const std::string mi = std::string(kAbend) + kYo + "behavior: goto_list\n  b_arg: args_from_file(enum) 10\n";
  CHECK(refusal("ma_missing", mi).find("m.mi:13: error: argument file goto_l10.ma not found") == 0);

  MissionDir bad_waypoint("ma_waypoint");
  bad_waypoint.ma("goto_l10.ma",
                  "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 1\n<end:b_arg>\n"
                  "<start:waypoints>\n713.000 5475.500\n<end:waypoints>\n");
  STRCMP_EQUAL("goto_l10.ma:6: error: waypoint is not a position in NMEA ddmm.mmm (lon lat)",
               refusal(bad_waypoint, mi).c_str());

  MissionDir too_few("ma_too_few");
  too_few.ma("goto_l10.ma",
             "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 3\n<end:b_arg>\n"
             "<start:waypoints>\n713.000 5433.500\n<end:waypoints>\n");
  STRCMP_EQUAL("m.mi:12: error: goto_list: num_waypoints 3 but 1 waypoints listed", refusal(too_few, mi).c_str());

  MissionDir no_list("ma_no_waypoints");
  no_list.ma("goto_l10.ma", "behavior_name=goto_list\n<start:b_arg>\nb_arg: num_waypoints(nodim) 1\n<end:b_arg>\n");
  CHECK(refusal(no_list, mi).find("m.mi:12: error: goto_list: no <start:waypoints> section") == 0);

  MissionDir unclosed("ma_unclosed");
  unclosed.ma("goto_l10.ma", "behavior_name=goto_list\n<start:waypoints>\n713.000 5433.500\n");
  STRCMP_EQUAL("goto_l10.ma:3: error: section not closed with <end:...>", refusal(unclosed, mi).c_str());

  MissionDir wrong_name("ma_wrong_name");
  wrong_name.ma("goto_l10.ma", "behavior_name=yo\n<start:waypoints>\n713.000 5433.500\n<end:waypoints>\n");
  CHECK(refusal(wrong_name, mi).find("goto_l10.ma:1: error: argument file is for behavior 'yo'") == 0);
}

TEST(MissionFile, UnsafeMissionsAreRefusedBeforeLaunch) {
  STRCMP_EQUAL("m.mi: error: no abend behavior: a mission without abort limits is refused",
               refusal("no_abend", kYo).c_str());
  std::string deep = std::string(kAbend) + kYo;
  deep.replace(deep.find("d_target_depth(m) 40"), 20, "d_target_depth(m) 150");
  deep.replace(deep.find("overdepth(m) 60"), 15, "overdepth(m) 200");
  STRCMP_EQUAL("m.mi:4: error: dive target 150.000000 m is beyond the vehicle's rating (102.000000 m)",
               refusal("too_deep", deep).c_str());
  std::string tight = std::string(kAbend) + kYo;
  tight.replace(tight.find("overdepth(m) 60"), 15, "overdepth(m) 42");
  CHECK(refusal("tight", tight).find("m.mi:4: error: dive target 40.000000 m leaves less than 5") == 0);
  STRCMP_EQUAL("m.mi:12: error: behavior goto_wpt is not supported: a mission that needs it is refused",
               refusal("unknown", std::string(kAbend) + kYo + "behavior: goto_wpt\n").c_str());
  STRCMP_EQUAL(
      "m.mi:4: error: abend: vacuum_min refused: no vacuum sensor in the HAL: the vacuum abort cannot be "
      "honoured",
      refusal("vacuum", std::string(kAbend) + "  b_arg: vacuum_min(inHg) 6\n" + kYo).c_str());
  STRCMP_EQUAL("m.mi:4: error: abend: argument max_speed is not supported (an abort limit the firmware cannot honour)",
               refusal("abend_unknown", std::string(kAbend) + "  b_arg: max_speed(m/s) 1\n" + kYo).c_str());
  std::string forever = std::string(kAbend) + kYo;
  forever.replace(forever.find("num_half_cycles_to_do(nodim) 4"), 30, "num_half_cycles_to_do(nodim) -1");
  CHECK(refusal("forever", forever).find("it would never surface") != std::string::npos);
  std::string nose_up_dive = std::string(kAbend) + kYo;
  nose_up_dive.replace(nose_up_dive.find("d_pitch_value(X) -0.45"), 22, "d_pitch_value(X) 0.45");
  STRCMP_EQUAL("m.mi:4: error: yo d_pitch_value must be nose down (< 0 rad)", refusal("nose_up", nose_up_dive).c_str());
  std::string far_battery = std::string(kAbend) + kYo;
  far_battery.replace(far_battery.find("d_use_pitch(enum) 3\n  b_arg: d_pitch_value(X) -0.45"), 50,
                      "d_use_pitch(enum) 1\n  b_arg: d_pitch_value(X) 2.50");
  CHECK(refusal("battery", far_battery).find("m.mi:9: error: yo d_pitch_value 2.5") == 0);
  STRCMP_EQUAL(
      "m.mi:12: error: surface: start_when 7 is not supported (1 stack idle, 9 every when_secs, 12 no comms "
      "for when_secs are)",
      refusal("surface", std::string(kAbend) + kYo + "behavior: surface\n b_arg: start_when(enum) 7\n").c_str());
}

TEST(MissionFile, HarmlessExtrasAreWarningsNotRefusals) {
  const LoadedMission m = MissionDir("harmless")
                              .load(std::string(kAbend) + kYo +
                                    "behavior: sample\n  b_arg: intersample_time(s) 0\n"
                                    "sensor: c_science_all_on_enabled(bool) 0\n");
  CHECK_TEXT(m.config.has_value(), all_text(m).c_str());
  const std::string text = all_text(m);
  CHECK(text.find("m.mi:12: warning: behavior sample") != std::string::npos);
  CHECK(text.find("m.mi:14: warning: sensor c_science_all_on_enabled") != std::string::npos);
}
