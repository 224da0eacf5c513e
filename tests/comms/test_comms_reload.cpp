// SPDX-License-Identifier: Apache-2.0
// Control-F over a call: a goto .ma with a NaN waypoint is refused (file:line
// and value named, in the console at once and in the next dialog) and the old
// plan is flown; once the file is fixed the re-read is taken.
#include <CppUTest/TestHarness.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glider/firmware/app/mission_reload.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"

using namespace glider;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

}  // namespace

TEST_GROUP(CommsReload){};

TEST(CommsReload, RefusedMafileKeepsTheOldPlanAndIsReportedInTheNextDialog) {
  const fs::path dir = fs::path(GLIDER_TEST_OUTPUT_DIR) / "comms_reload";
  fs::remove_all(dir);
  fs::copy(GLIDER_SOURCE_DIR "/boards/missions/box_current", dir, fs::copy_options::recursive);
  const fs::path goto_ma = dir / "mafiles" / "goto_l10.ma";
  const std::string good = read(goto_ma);
  std::string bad = good;
  bad.replace(bad.find("726.4381 5420.0452"), 18, "nan 5420.0452");

  const model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  fw::app::FittedDevices fitted{.drop_weight = false, .leak_detector = true, .rudder = true, .power_monitor = true};
  const fw::app::VehicleSetup setup = sil::vehicle_setup(vehicle, fitted, 200.0, false, 1025.0);
  const fs::path mi = dir / "missions" / "box.mi";
  const fw::app::PreparedMission prepared = fw::app::prepare_mission(mi, setup, {});
  CHECK_TRUE(prepared.config.has_value());
  fw::app::MissionFileReloader reloader(mi, setup, {});

  sil::FakeShore shore;
  shore.script = {{20.0, "\x06"}, {200.0, "\x06"}};
  sil::ScenarioOptions options;
  options.max_sim_time_s = 700.0;
  options.fitted = fitted;
  options.comms.emplace();
  std::snprintf(options.comms->config.vehicle_name, 40, "unit_345");
  std::snprintf(options.comms->config.primary_number, 40, "0088160000519");
  options.comms->link = {.availability = 1.0, .connect_probability = 1.0, .drops_per_hour = 0.0};
  options.comms->far_end = &shore;
  options.comms->reloader = &reloader;
  write(goto_ma, bad);
  bool fixed = false;
  options.comms->after_cycle = [&](double, const fw::comms::CommsTask&) {
    if (!fixed && shore.transcript().find("mafiles refused") != std::string::npos) {
      write(goto_ma, good);  // the pilot sends a corrected file
      fixed = true;
    }
  };
  fw::FlightSoftwareConfig config = *prepared.config;
  config.plan.surface_dwell_s = 300.0;  // the pilot's keystroke wait (box.mi quits at once: end_action 0)
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  STRCMP_EQUAL("", r.error.c_str());
  const std::string& t = shore.transcript();
  if (t.find("mafiles refused") == std::string::npos) {
    std::printf("\nsim %.0f s, surfacings %u, dials %u, connected %u, numbers %zu, completed %d\n%s\n", r.sim_time_s,
                r.comms.surfacings, r.comms.dial_attempts, r.comms.calls_connected, shore.numbers().size(), r.completed,
                t.substr(0, 3000).c_str());
  }
  const std::size_t refused = t.find("^F\r\nmafiles refused (the old plan is flown): ");
  CHECK(refused != std::string::npos);
  const std::string line = t.substr(refused, t.find("\r\n", refused + 6) - refused);
  STRCMP_CONTAINS("goto_l10.ma:", line.c_str());
  STRCMP_CONTAINS("nan", line.c_str());
  // The next dialog carries the refusal once.
  const std::size_t next_dialog = t.find("Glider unit_345 at surface.", refused);
  CHECK(next_dialog != std::string::npos);
  CHECK(t.find("Control-F refused: ", next_dialog) != std::string::npos);
  // Fixed file: taken.
  STRCMP_CONTAINS("^F\r\nmafiles re-read", t.c_str());
}
