// SPDX-License-Identifier: Apache-2.0
// Which files make a deployment and in what order; the tools' loader (CSV or
// binaries) with the CSV reader's checks.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

#include "file_surgery.hpp"
#include "glider/slocum/csv_export.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/slocum/log_loader.hpp"
#include "reference.hpp"

namespace {
namespace fs = std::filesystem;
namespace t = glider::slocum::test;

std::vector<std::string> names(const std::vector<fs::path>& paths) {
  std::vector<std::string> out;
  for (const auto& p : paths) out.push_back(p.filename().string());
  return out;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + " ";
  return s;
}

}  // namespace

TEST_GROUP(SlocumDeployment){};

TEST(SlocumDeployment, FilesInSegmentOrderNotStringOrder) {
  const fs::path dir = t::output_dir() / "slocum" / "order";
  fs::remove_all(dir);
  for (const char* name : {"g-2016-174-5-10.dbd", "g-2016-174-5-9.ebd", "g-2016-174-5-9.dbd", "g-2016-99-0-0.DBD",
                           "g-2017-1-0-0.dcd", "g-2016-174-5-9.tbd", "notes.txt", "g-2016-174-5-9.mlg"}) {
    t::write_bytes(dir / name, "x");
  }
  STRCMP_EQUAL(
      "g-2016-99-0-0.DBD g-2016-174-5-9.dbd g-2016-174-5-9.ebd g-2016-174-5-9.tbd g-2016-174-5-10.dbd "
      "g-2017-1-0-0.dcd ",
      joined(names(glider::slocum::deployment_files({dir.string()}))).c_str());
  // A glob and a list give the same order.
  STRCMP_EQUAL("g-2016-174-5-9.dbd g-2016-174-5-10.dbd ",
               joined(names(glider::slocum::deployment_files(
                          {(dir / "g-2016-174-5-10.dbd").string(), (dir / "g-2016-174-5-9.dbd").string()})))
                   .c_str());
  STRCMP_EQUAL("g-2016-174-5-9.dbd g-2016-174-5-10.dbd ",
               joined(names(glider::slocum::deployment_files({(dir / "g-2016-174-*.dbd").string()}))).c_str());
}

TEST(SlocumDeployment, BadInputsAreNamed) {
  try {
    glider::slocum::deployment_files({"/nonexistent/x.dbd"});
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    STRCMP_EQUAL("/nonexistent/x.dbd: no such file or directory", e.what());
  }
  try {
    glider::slocum::deployment_files({(t::real_dbd_dir() / "comet-2016" / "LICENSE").string()});
    FAIL("no error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("not a Slocum data file name") != std::string::npos);
  }
}

TEST(SlocumDeployment, LoaderReadsBinariesWithTheCsvReadersChecks) {
  glider::flightlog::ReadOptions options;
  options.columns = {"m_depth", "m_pitch", "sci_water_temp"};
  const glider::slocum::LogSource source{{(t::real_dbd_dir() / "comet-2016").string()}, {}};
  const auto binary = glider::slocum::load_flight_log(source, options);
  const auto csv = glider::flightlog::read_flight_log(t::real_dbd_dir() / ".." / "comet-2016-174-05.csv", options);
  CHECK_EQUAL(csv.rows(), binary.rows());
  for (const char* name : {"m_present_time", "m_depth", "m_pitch", "m_ballast_pumped", "sci_water_temp"}) {
    CHECK_TEXT(binary.has(name), name);
    const auto& a = binary.column(name);
    const auto& b = csv.column(name);
    for (std::size_t r = 0; r < a.size(); ++r) {
      // The CSV holds 7 significant digits (10 us for time).
      CHECK_TEXT(std::isnan(a[r]) == std::isnan(b[r]), name);
      if (!std::isnan(a[r])) DOUBLES_EQUAL(b[r], a[r], std::fabs(b[r]) * 1e-6 + 1e-5);
    }
  }
  options.required.push_back({"m_nonexistent", "m_other"});
  try {
    glider::slocum::load_flight_log(source, options);
    FAIL("no error");
  } catch (const glider::flightlog::FlightLogError& e) {
    STRCMP_EQUAL("m_nonexistent", e.column_name().c_str());
    CHECK(std::string(e.what()).find("required column missing from the binary files (nor m_other)") !=
          std::string::npos);
  }
}

TEST(SlocumDeployment, LoaderReadsScienceFilesAloneAsConvertDoes) {
  const std::string ebd = (t::real_dbd_dir() / "comet-2019" / "comet-2019-222-02-154.ebd").string();
  glider::flightlog::ReadOptions options;
  options.required.clear();
  const auto log = glider::slocum::load_flight_log({{ebd}, {}}, options);
  const auto convert = glider::slocum::read_deployment(glider::slocum::deployment_files({ebd}), {});
  STRCMP_EQUAL("sci_m_present_time", log.column_names().front().c_str());
  CHECK_EQUAL(convert.log.rows(), log.rows());
  CHECK(convert.log.column_names() == log.column_names());
  // A tool that needs the flight computer's sensors is told which one is missing, not the time.
  try {
    glider::slocum::load_flight_log({{ebd}, {}}, glider::flightlog::ReadOptions{});
    FAIL("no error");
  } catch (const glider::flightlog::FlightLogError& e) {
    STRCMP_EQUAL("m_pitch", e.column_name().c_str());
  }
  // The CSV glider-convert writes of them loads as well, timed the same way.
  std::ostringstream csv;
  glider::slocum::write_csv(convert, csv);
  const auto csv_path = std::filesystem::temp_directory_path() / "glider_slocum_tests_science_only.csv";
  glider::slocum::test::write_bytes(csv_path, csv.str());
  const auto from_csv = glider::slocum::load_flight_log({{csv_path.string()}, {}}, options);
  std::filesystem::remove(csv_path);
  STRCMP_EQUAL("sci_m_present_time", from_csv.column_names().front().c_str());
  CHECK_EQUAL(log.rows(), from_csv.rows());
  // Another time column asked for by name is still refused.
  options.time_column = "m_present_time_other";
  CHECK_THROWS(glider::flightlog::FlightLogError, glider::slocum::load_flight_log({{ebd}, {}}, options));
}

TEST(SlocumDeployment, ScienceFilesAloneUseTheScienceTime) {
  glider::slocum::DeploymentOptions options;
  options.columns = {"sci_water_temp"};
  const auto deployment = glider::slocum::read_deployment(
      glider::slocum::deployment_files({(t::real_dbd_dir() / "comet-2019" / "*.ebd").string()}), options);
  STRCMP_EQUAL("sci_m_present_time", deployment.log.column_names().front().c_str());
  CHECK_EQUAL(3U, deployment.files.size());
  CHECK(deployment.log.rows() > 10000);
}
