// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/seawater.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"

using glider::config::ConfigError;
using glider::config::TomlDocument;

namespace {

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

const std::string kVehicle = GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml";
const std::string kMission = GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml";

// The error message a vehicle text produces (empty if it loads).
std::string vehicle_error(const std::string& text) {
  try {
    glider::model::parse_vehicle_text(text, "bad.toml");
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

std::string mission_error(const std::string& text) {
  try {
    const TomlDocument doc = TomlDocument::parse(text, "bad_mission.toml");
    glider::fw::read_flight_config(doc);
    doc.reject_unknown_keys();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "";
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  CHECK_TRUE(at != std::string::npos);
  text.replace(at, from.size(), to);
}

}  // namespace

TEST_GROUP(ConfigFiles) {
  std::string vehicle = read_text(kVehicle);
  std::string mission = read_text(kMission);
};

TEST(ConfigFiles, ShippedFilesLoad) {
  const glider::model::VehicleParams v = glider::model::load_vehicle_file(kVehicle);
  STRCMP_EQUAL("slocum_we01", v.name.c_str());
  DOUBLES_EQUAL(9.1, v.battery.mass_kg, 0.0);
  DOUBLES_EQUAL(52.0, glider::model::dry_mass_kg(v), 1e-9);
  STRCMP_EQUAL("", mission_error(mission).c_str());
}

TEST(ConfigFiles, MetadataRoundTripsEveryParameter) {
  const glider::model::VehicleParams v = glider::model::load_vehicle_file(kVehicle);
  const auto meta = glider::model::vehicle_metadata(v);
  // Rebuild a vehicle file from the metadata and load it again.
  std::string rebuilt;
  std::string table;
  for (const auto& [meta_key, value] : meta) {
    CHECK_TRUE(meta_key.rfind("vehicle.", 0) == 0);
    std::string key = meta_key.substr(8);
    if (key == "name") key = "vehicle.name";
    const std::size_t dot = key.rfind('.');
    const std::string section = key.substr(0, dot);
    if (section != table) {
      rebuilt += "[" + section + "]\n";
      table = section;
    }
    const bool text = key == "vehicle.name";
    rebuilt += key.substr(dot + 1) + " = " + (text ? "\"" + value + "\"" : value) + "\n";
  }
  const glider::model::VehicleParams back = glider::model::parse_vehicle_text(rebuilt, "rebuilt.toml");
  DOUBLES_EQUAL(v.hydro.cd0, back.hydro.cd0, 0.0);
  DOUBLES_EQUAL(v.battery.x_at_zero_m, back.battery.x_at_zero_m, 0.0);
  DOUBLES_EQUAL(v.buoyancy_offset_kg, back.buoyancy_offset_kg, 0.0);
}

TEST(ConfigFiles, UnknownKeyNamesFileAndLine) {
  replace(vehicle, "cd0 = 0.214", "cd_0 = 0.214");
  const std::string error = vehicle_error(vehicle);
  // The misspelt key is reported as missing (required) first.
  CHECK(error.find("hydrodynamics.cd0") != std::string::npos);
  std::string extra = read_text(kVehicle) + "\n[hydrodynamics.extra]\nfoo = 1\n";
  const std::string unknown = vehicle_error(extra);
  CHECK(unknown.find("bad.toml:") == 0);
  CHECK(unknown.find("unknown key 'hydrodynamics.extra.foo'") != std::string::npos);
  const std::size_t lines = static_cast<std::size_t>(std::count(extra.begin(), extra.end(), '\n'));
  const std::string last_line = std::string(":").append(std::to_string(lines)).append(":");
  CHECK(unknown.find(last_line) != std::string::npos);  // the last line
}

TEST(ConfigFiles, WrongTypeNamesTheLine) {
  replace(vehicle, "mass_kg = 9.1", "mass_kg = \"heavy\"");
  const std::string error = vehicle_error(vehicle);
  CHECK(error.find("battery.mass_kg: expected a number") != std::string::npos);
  // Line of the bad value in the file.
  const std::size_t at = vehicle.find("mass_kg = \"heavy\"");
  const long line = std::count(vehicle.begin(), vehicle.begin() + static_cast<long>(at), '\n') + 1;
  CHECK(error.find("bad.toml:" + std::to_string(line) + ":") == 0);
}

TEST(ConfigFiles, SyntaxErrorNamesTheLine) {
  const std::string error = vehicle_error("[vehicle]\nname = \"x\"\n\n[mass\nhull_kg = 1\n");
  CHECK(error.find("bad.toml:4:") == 0);
}

TEST(ConfigFiles, PhysicallyImpossibleVehicleIsRefused) {
  replace(vehicle, "hull_kg = 6.9", "hull_kg = -6.9");
  STRCMP_CONTAINS("mass.hull_kg: value -6.9 is outside the allowed range [0.1, 1000] kg",
                  vehicle_error(vehicle).c_str());
}

TEST(ConfigFiles, UnflyableMissionIsRefusedBeforeLaunch) {
  replace(mission, "dive_to_m = 50.0", "dive_to_m = 3.0");
  const std::string error = mission_error(mission);
  CHECK(error.find("bad_mission.toml: mission refused: dive_to_m must be deeper than climb_to_m") == 0);
}

TEST(ConfigFiles, MissingFileIsAClearError) {
  try {
    glider::model::load_vehicle_file("/nonexistent/vehicle.toml");
    FAIL("expected an error");
  } catch (const ConfigError& error) {
    STRCMP_EQUAL("/nonexistent/vehicle.toml: no such file", error.what());
  }
}

TEST(ConfigFiles, EveryShippedVehicleLoadsAndGlides) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(GLIDER_SOURCE_DIR "/boards/vehicles")) {
    if (entry.path().extension() != ".toml") continue;
    const glider::model::VehicleParams v = glider::model::load_vehicle_file(entry.path());
    const glider::model::GliderDynamics dyn(v, glider::model::still_water(v.trim_density_kg_m3));
    const glider::model::TrimResult trim = glider::model::solve_trim(dyn, 30.0, 0.1, 10.0);
    CHECK_TRUE_TEXT(trim.trim.has_value(), entry.path().c_str());
    CHECK_TRUE_TEXT(trim.trim->within_limits, entry.path().c_str());
    ++count;
  }
  LONGS_EQUAL(6, count);  // WE01, comet (WE01 as comet flew), the identified shallow Slocum, Stante's, IIT Madras, USM
}

namespace {

// The message an environment file text is refused with ("" if accepted).
std::string environment_error_of(const std::string& text) {
  try {
    glider::model::parse_environment_text(text, "env.toml");
  } catch (const ConfigError& e) {
    return std::string(e.what());
  }
  return std::string();
}

}  // namespace

TEST(ConfigFiles, EnvironmentFileErrorsNameTheLine) {
  const auto env = glider::model::load_environment_file(GLIDER_SOURCE_DIR "/boards/environments/tidal_shelf.toml");
  DOUBLES_EQUAL(1026.2, env.water.at(30.0, 0.0).density_kg_m3, 1e-12);
  CHECK(environment_error_of("[profile]\ndepth_m = [0, 10]\ndensity_kg_m3 = [1025]\n").find("env.toml:3:") ==
        0);  // one value for two depths
  CHECK(environment_error_of("[profile]\ndepth_m = [10, 0]\n").find("strictly") != std::string::npos);
  CHECK(environment_error_of("[profile]\ndepth_m = [0, \"x\"]\n").find("env.toml:2:") == 0);
  CHECK(environment_error_of("[profile]\ndepth_m = [0]\ncurent_east_m_s = [0.1]\n")
            .find("unknown key 'profile.curent_east_m_s'") != std::string::npos);
}

TEST(ConfigFiles, EnvironmentWithSalinityIsTeos10Water) {
  // A Baltic summer column: warm brackish water over a cold, saltier layer.
  const auto env = glider::model::parse_environment_text(
      "[profile]\ndepth_m = [0, 20, 40]\ntemperature_c = [17.0, 12.0, 5.0]\n"
      "practical_salinity = [7.0, 7.5, 9.0]\n",
      "baltic.toml");
  CHECK_TRUE(env.water.has_salinity());
  namespace sw = glider::model::seawater;
  // The density the vehicle feels anywhere is what a CTD there measures:
  // TEOS-10 of the water's T, S at the column's pressure, including between
  // nodes and below the last one.
  for (double depth : {0.0, 7.3, 20.0, 31.0, 40.0, 95.0}) {
    const auto w = env.water.at(depth, 0.0);
    const double p = glider::model::sea_pressure_dbar(depth);
    const double c = sw::conductivity_from_practical_salinity(w.practical_salinity, w.temperature_c, p);
    DOUBLES_EQUAL(sw::density_from_ctd(c, w.temperature_c, p), w.density_kg_m3, 1e-9);
  }
  CHECK(env.water.at(0.0, 0.0).density_kg_m3 > 1004.0 && env.water.at(0.0, 0.0).density_kg_m3 < 1005.0);
  CHECK(env.water.at(40.0, 0.0).density_kg_m3 > 1007.0 && env.water.at(40.0, 0.0).density_kg_m3 < 1007.5);
  DOUBLES_EQUAL(env.water.at(20.0, 0.0).density_kg_m3, env.water.nodes()[1].water.density_kg_m3, 0.0);
  // A density-only column keeps working, with no salinity.
  CHECK_FALSE(glider::model::still_water(1025.0).water.has_salinity());
  CHECK(std::isnan(glider::model::still_water(1025.0).water.at(10.0, 0.0).practical_salinity));

  CHECK(environment_error_of("[profile]\ndepth_m = [0]\ntemperature_c = [10]\npractical_salinity = [35]\n"
                             "density_kg_m3 = [1025]\n")
            .find("not both") != std::string::npos);
  CHECK(environment_error_of("[profile]\ndepth_m = [0]\npractical_salinity = [35]\n").find("needs temperature_c") !=
        std::string::npos);
  // An empty optional column is refused (file:line:column), not read as absent.
  for (const char* column : {"practical_salinity", "temperature_c", "density_kg_m3", "current_east_m_s"}) {
    const std::string error = environment_error_of(std::string("[profile]\ndepth_m = [0, 10]\n") + column + " = []\n");
    CHECK_EQUAL(0u, error.find("env.toml:3:"));
    STRCMP_CONTAINS((std::string("profile.") + column).c_str(), error.c_str());
    STRCMP_CONTAINS("is empty: give one value per depth (2), or leave the key out", error.c_str());
  }
  CHECK(environment_error_of("[profile]\ndepth_m = [0]\ntemperature_c = [10]\npractical_salinity = [45]\n")
            .find("value 45 is outside the allowed range [0, 42]") != std::string::npos);
}

TEST(ConfigFiles, VehicleFileTextAndLogMetadataRoundTrip) {
  const auto v = glider::model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/iitm_lab_glider.toml");
  const auto back = glider::model::parse_vehicle_text(glider::model::vehicle_file_text(v), "written.toml");
  DOUBLES_EQUAL(v.second_mass.mass_kg, back.second_mass.mass_kg, 0.0);
  DOUBLES_EQUAL(v.hydro.cl0, back.hydro.cl0, 0.0);
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& [key, value] : glider::model::vehicle_metadata(v)) entries.emplace_back(key.substr(8), value);
  const auto from_log = glider::model::vehicle_from_metadata(entries, "log.csv");
  STRCMP_EQUAL("iitm_lab_glider", from_log.name.c_str());
  DOUBLES_EQUAL(v.ballast.x_m, from_log.ballast.x_m, 0.0);
}

TEST(ConfigFiles, WingsRoundTripAndStayOutOfWinglessLogs) {
  const auto v = glider::model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml");
  const auto back = glider::model::parse_vehicle_text(glider::model::vehicle_file_text(v), "written.toml");
  DOUBLES_EQUAL(v.hydro.wing_area_m2, back.hydro.wing_area_m2, 0.0);
  DOUBLES_EQUAL(v.hydro.wing_aspect_ratio, back.hydro.wing_aspect_ratio, 0.0);
  DOUBLES_EQUAL(v.hydro.wing_sweep_rad, back.hydro.wing_sweep_rad, 0.0);
  DOUBLES_EQUAL(v.hydro.wing_oswald_efficiency, back.hydro.wing_oswald_efficiency, 0.0);
  // A vehicle without wings logs no wing keys: its logs are those it wrote before the keys existed.
  for (const auto& [key, value] : glider::model::vehicle_metadata(glider::model::load_vehicle_file(kVehicle))) {
    CHECK_TEXT(key.find("wing_") == std::string::npos, key.c_str());
  }
}

TEST(ConfigFiles, WingKeysNeedEachOther) {
  std::string no_area = vehicle;
  replace(no_area, "cd0 = 0.214", "cd0 = 0.214\nwing_aspect_ratio = 7.0");
  STRCMP_CONTAINS("the wing keys need wing_area_m2", vehicle_error(no_area).c_str());
  std::string no_shape = vehicle;
  replace(no_shape, "cd0 = 0.214", "cd0 = 0.214\nwing_area_m2 = 0.1");
  STRCMP_CONTAINS("wing_aspect_ratio and wing_oswald_efficiency must be positive", vehicle_error(no_shape).c_str());
  std::string swept_back = vehicle;
  replace(swept_back, "cd0 = 0.214", "cd0 = 0.214\nwing_sweep_rad = 2.0");
  STRCMP_CONTAINS("hydrodynamics.wing_sweep_rad: value 2 is outside the allowed range [0, 1.4] rad",
                  vehicle_error(swept_back).c_str());
}
