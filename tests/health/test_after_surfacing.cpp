// SPDX-License-Identifier: Apache-2.0
// The shore's hook after a surfacing event (tools/shore/station/after_surfacing.cpp):
// on a glider folder it writes health/ (state, report, vehicle file, plots)
// and says so in one note, then the forecast its own; on a folder it cannot use it says why in a note
// and never throws (a call must never break on it).
#include <CppUTest/TestHarness.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "after_surfacing.hpp"
#include "sil_deployment.hpp"

using namespace glider;
namespace fs = std::filesystem;

TEST_GROUP(HealthAfterSurfacing){};

TEST(HealthAfterSurfacing, WritesHealthAndNeverThrows) {
  const fs::path root = fs::path(GLIDER_TEST_OUTPUT_DIR) / "health/shore";
  fs::remove_all(root);
  // A SIL glider's folder: its times are real clocks at the shore, so the
  // SIL's files (clock from 0) are refused there: the note says so.
  const fs::path glider = root / "slocum_we01";
  CHECK(health_sil::fly_surfacing((glider / "from-glider").string(), {}, 0, 8.0, 41).empty());
  fs::copy_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml", glider / "vehicle.toml");
  std::vector<std::string> notes = shore::after_surfacing(glider);
  CHECK_EQUAL(2u, notes.size());  // health's, then the forecast's
  CHECK_TEXT(notes[1].find("forecast: ") == 0, notes[1].c_str());
  CHECK_TEXT(
      notes[0].find("health: failed: ") == 0 && notes[0].find("its times count from its start") != std::string::npos,
      notes[0].c_str());

  // The real comet deployment's files as they arrive at the shore: ok.
  const fs::path comet = root / "comet";
  fs::create_directories(comet / "from-glider");
  for (const auto& e : fs::directory_iterator(GLIDER_SOURCE_DIR "/tests/data/real/dbd/comet-2016")) {
    fs::copy(e.path(), comet / "from-glider" / e.path().filename(), fs::copy_options::recursive);
  }
  notes = shore::after_surfacing(comet);
  CHECK_EQUAL(2u, notes.size());  // health's, then the forecast's
  CHECK_TEXT(notes[1].find("forecast: ") == 0, notes[1].c_str());
  CHECK_TEXT(notes[0].find("health: ok, 10 segments (10 measured now") == 0, notes[0].c_str());
  for (const char* file : {"health/state.json", "health/health.json", "health/vehicle.toml"}) {
    CHECK_TEXT(fs::is_regular_file(comet / file), file);
  }
  std::ifstream in(comet / "health/health.json");
  const nlohmann::json report = nlohmann::json::parse(in);
  STRCMP_EQUAL("glider-health/1", report.at("schema").get<std::string>().c_str());
  STRCMP_EQUAL("comet", report.at("glider").get<std::string>().c_str());
  CHECK_EQUAL(7u, report.at("effects").size());
  if (fs::exists("/usr/bin/gnuplot")) CHECK(fs::is_regular_file(comet / "health/plots/drag_change.png"));
  // The next call with nothing new: every segment from the state.
  notes = shore::after_surfacing(comet);
  CHECK_TEXT(notes[0].find("(0 measured now") != std::string::npos, notes[0].c_str());
  // No mission copy in the folder: the forecast says so in its note and its file.
  CHECK_TEXT(notes[1].find("forecast: failed: ") == 0, notes[1].c_str());
  CHECK(fs::is_regular_file(comet / "forecast/forecast.json"));

  // No folder at all, and a glider nobody knows: notes, no exception.
  notes = shore::after_surfacing(root / "nobody");
  CHECK_TEXT(notes.size() == 2 && notes[0].find("health: failed: ") == 0, notes[0].c_str());
  fs::create_directories(root / "unknown/from-glider");
  fs::copy_file(glider / "from-glider/slocum_we01-1970-000-00-000.sbd",
                root / "unknown/from-glider/unknown-2026-331-0-0.sbd");
  notes = shore::after_surfacing(root / "unknown");
  CHECK_TEXT(notes.size() == 2 && notes[0].find("health: failed: ") == 0, notes[0].c_str());
}
