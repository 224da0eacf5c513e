// SPDX-License-Identifier: Apache-2.0
// The SIL's binary log (firmware/log/binary_rows.hpp): the same run written
// as CSV and as .glb converts back to the same bytes, the reader reads it
// directly, and a cut or damaged file is handled like a cut CSV.
#include <CppUTest/TestHarness.h>

#include <bit>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/flightlog/binary_log.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/scenario.hpp"

using namespace glider;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return std::move(bytes).str();
}

void spill(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
}

// The demo mission with the log thinned like a real one (empty science
// fields, surface gaps), written to `path`.
sil::ScenarioResult fly_demo(const std::string& path) {
  const auto vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  const auto config =
      fw::read_flight_config(config::TomlDocument::load(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"));
  sil::ScenarioOptions options;
  options.log_path = path;
  options.log_gaps.enabled = true;
  return sil::run_scenario(vehicle, config, options);
}

// Where each record starts (after the header line: 'R', the 8-byte mask,
// 8 bytes per bit set), and last where the records end.
std::vector<std::size_t> record_starts(const std::string& glb) {
  std::size_t at = 0;
  while (glb[at] == '#') at = glb.find('\n', at) + 1;
  at = glb.find('\n', at) + 1;  // the header
  std::vector<std::size_t> starts;
  while (at < glb.size() && glb[at] == 'R') {
    starts.push_back(at);
    std::uint64_t mask = 0;
    for (int i = 8; i >= 1; --i) mask = (mask << 8) | static_cast<unsigned char>(glb[at + static_cast<std::size_t>(i)]);
    at += 9 + 8 * static_cast<std::size_t>(std::popcount(mask));
  }
  starts.push_back(at);
  return starts;
}

}  // namespace

TEST_GROUP(BinaryLog) {
  const std::string csv_path = GLIDER_TEST_OUTPUT_DIR "/binary_log_demo.csv";
  const std::string glb_path = GLIDER_TEST_OUTPUT_DIR "/binary_log_demo.glb";
};

TEST(BinaryLog, ConvertsBackToTheSameCsvBytes) {
  const sil::ScenarioResult csv_run = fly_demo(csv_path);
  const sil::ScenarioResult glb_run = fly_demo(glb_path);
  STRCMP_EQUAL("", csv_run.error.c_str());
  STRCMP_EQUAL("", glb_run.error.c_str());
  LONGS_EQUAL(csv_run.log_rows, glb_run.log_rows);
  const std::string csv = slurp(csv_path);
  const std::string glb = slurp(glb_path);
  CHECK_TRUE(flightlog::is_binary_rows_log(glb));
  CHECK_FALSE(flightlog::is_binary_rows_log(csv));
  CHECK(glb.size() * 2 < csv.size());  // compact too
  std::string error;
  const std::string converted = flightlog::binary_rows_to_csv(glb, error);
  STRCMP_EQUAL("", error.c_str());
  CHECK_TRUE(converted == csv);

  // Every tool reads the .glb directly, as the CSV: same rows, same end.
  const flightlog::FlightLog from_csv = flightlog::read_flight_log(csv_path);
  const flightlog::FlightLog from_glb = flightlog::read_flight_log(glb_path);
  LONGS_EQUAL(from_csv.rows(), from_glb.rows());
  CHECK_TRUE(from_glb.end().state == flightlog::LogEnd::State::kComplete);
  LONGS_EQUAL(glb_run.log_rows, from_glb.end().trailer_rows);
  STRCMP_EQUAL("glider-sil", from_glb.metadata_value("writer").value_or("").c_str());
}

TEST(BinaryLog, ACutFileLosesOnlyItsLastRecord) {
  const sil::ScenarioResult run = fly_demo(glb_path);
  STRCMP_EQUAL("", run.error.c_str());
  std::string glb = slurp(glb_path);
  const std::vector<std::size_t> starts = record_starts(glb);
  LONGS_EQUAL(run.log_rows + 1, starts.size());
  STRCMP_EQUAL("# end:", glb.substr(starts.back(), 6).c_str());  // the records end at the trailer
  // Cut 5 bytes into the last record (a killed writer): no trailer, the
  // torn record dropped and reported, every whole row before it read.
  const std::string cut_path = GLIDER_TEST_OUTPUT_DIR "/binary_log_cut.glb";
  const std::size_t last_record = starts[starts.size() - 2];
  spill(cut_path, glb.substr(0, last_record + 5));
  const flightlog::FlightLog cut = flightlog::read_flight_log(cut_path);
  CHECK_TRUE(cut.end().state == flightlog::LogEnd::State::kNoTrailer);
  CHECK(cut.end().torn_line > 0);
  LONGS_EQUAL(run.log_rows - 1, cut.rows());

  // A byte that starts no record is an error naming where, never a crash.
  const std::string bad_path = GLIDER_TEST_OUTPUT_DIR "/binary_log_bad.glb";
  glb[last_record] = 'X';
  spill(bad_path, glb);
  try {
    (void)flightlog::read_flight_log(bad_path);
    FAIL("a damaged binary log was read");
  } catch (const flightlog::FlightLogError& e) {
    CHECK(std::string(e.what()).find("not a record") != std::string::npos);
  }
}
