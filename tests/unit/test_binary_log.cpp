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
sil::ScenarioResult fly_demo(const std::string& path, bool thinned = true) {
  const auto vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  const auto config =
      fw::read_flight_config(config::TomlDocument::load(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"));
  sil::ScenarioOptions options;
  options.log_path = path;
  options.log_gaps.enabled = thinned;
  return sil::run_scenario(vehicle, config, options);
}

// Where each record starts (after the header line: 'R', the 8-byte mask,
// 8 bytes per bit set), and last where the records end; `checks` gets where
// each check record starts ('C', 8 bytes).
std::vector<std::size_t> record_starts(const std::string& glb, std::vector<std::size_t>* checks = nullptr) {
  std::size_t at = 0;
  while (glb[at] == '#') at = glb.find('\n', at) + 1;
  at = glb.find('\n', at) + 1;  // the header
  std::vector<std::size_t> starts;
  while (at < glb.size() && (glb[at] == 'R' || glb[at] == 'C')) {
    if (glb[at] == 'C') {
      if (checks != nullptr) checks->push_back(at);
      at += 9;
      continue;
    }
    starts.push_back(at);
    std::uint64_t mask = 0;
    for (int i = 8; i >= 1; --i) mask = (mask << 8) | static_cast<unsigned char>(glb[at + static_cast<std::size_t>(i)]);
    at += 9 + 8 * static_cast<std::size_t>(std::popcount(mask));
  }
  starts.push_back(at);
  const std::size_t after_trailer = glb.find('\n', at) + 1;  // the last block's check
  if (checks != nullptr && after_trailer > 0 && after_trailer < glb.size() && glb[after_trailer] == 'C') {
    checks->push_back(after_trailer);
  }
  return starts;
}

// True if `bytes` read as a finished flight with nothing unchecked: what a
// damaged file must never do.
bool reads_as_complete(const std::string& bytes) {
  try {
    const flightlog::FlightLog log = flightlog::parse_flight_log(bytes, "flipped.glb");
    return log.end().complete() && !log.end().unfinished();
  } catch (const flightlog::FlightLogError&) {
    return false;
  }
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
  // The rows after the last check record are read, and said to be unchecked.
  STRCMP_CONTAINS("have no check record after them: unchecked", cut.end().unchecked.c_str());
  STRCMP_CONTAINS("unchecked", cut.end().describe(cut.rows()).c_str());

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

// binary-rows-2's block checks (CRC-32 per block, the text lines and the
// trailer covered): a single flipped bit anywhere in a finished file is an
// error or at least not a complete flight. Before them (binary-rows-1),
// 10 of 10 random flips read as complete.
TEST(BinaryLog, EveryFlippedBitIsFound) {
  const sil::ScenarioResult run = fly_demo(glb_path, false);  // 1 row per second: 4 blocks
  STRCMP_EQUAL("", run.error.c_str());
  const std::string glb = slurp(glb_path);
  CHECK_TRUE(reads_as_complete(glb));
  std::vector<std::size_t> checks;
  const std::vector<std::size_t> starts = record_starts(glb, &checks);
  CHECK(checks.size() >= 3);                   // a block per 64 KiB flush, the last one after the trailer
  LONGS_EQUAL(glb.size() - 9, checks.back());  // the file ends in a check record
  // Every bit of: 64 bytes spread over the text lines, the tag and mask of
  // the first and the last record, each check record, the trailer; then 400
  // seeded random bits (each flip is a whole read of the 200 KB file).
  std::vector<std::size_t> bytes;
  for (std::size_t i = 0; i < 64; ++i) bytes.push_back(i * starts[0] / 64);
  for (const std::size_t record : {starts[0], starts[starts.size() - 2]}) {
    for (std::size_t i = record; i < record + 9; ++i) bytes.push_back(i);
  }
  for (std::size_t i = starts.back(); i < glb.size(); ++i) bytes.push_back(i);  // trailer, last check
  for (const std::size_t check : checks) {
    for (std::size_t i = check; i < check + 9; ++i) bytes.push_back(i);
  }
  std::size_t flips = 0;
  std::string flipped = glb;
  const auto try_flip = [&](std::size_t at, int bit) {
    flipped[at] = static_cast<char>(glb[at] ^ (1 << bit));
    if (reads_as_complete(flipped)) {
      FAIL(("a flip of bit " + std::to_string(bit) + " of byte " + std::to_string(at) + " read as complete").c_str());
    }
    flipped[at] = glb[at];
    ++flips;
  };
  for (const std::size_t at : bytes) {
    for (int bit = 0; bit < 8; ++bit) try_flip(at, bit);
  }
  std::uint64_t state = 20261127;
  for (int i = 0; i < 400; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    try_flip(static_cast<std::size_t>((state >> 33) % glb.size()), static_cast<int>((state >> 20) % 8));
  }
  CHECK(flips > 1500);
}

// A file written before the checks (binary-rows-1: the same records, no
// check records) is still read, with a note that damage cannot be detected.
TEST(BinaryLog, AnOldFileWithoutChecksIsReadWithANote) {
  const sil::ScenarioResult run = fly_demo(glb_path);
  STRCMP_EQUAL("", run.error.c_str());
  const std::string glb = slurp(glb_path);
  std::vector<std::size_t> checks;
  (void)record_starts(glb, &checks);
  std::string old;
  std::size_t from = 0;
  for (const std::size_t check : checks) {
    old += glb.substr(from, check - from);
    from = check + 9;
  }
  const std::string v2 = "# encoding: binary-rows-2\n";
  const std::size_t line = old.find(v2);
  CHECK(line != std::string::npos);
  old.replace(line, v2.size(), "# encoding: binary-rows-1\n");
  const flightlog::FlightLog log = flightlog::parse_flight_log(old, "old.glb");
  LONGS_EQUAL(run.log_rows, log.rows());
  CHECK_TRUE(log.end().complete());
  STRCMP_CONTAINS("binary-rows-1 (written before block checks): damage cannot be detected",
                  log.end().describe(log.rows()).c_str());
  // And converted back to the same CSV as the checked file.
  std::string error;
  const std::string from_old = flightlog::binary_rows_to_csv(old, error);
  STRCMP_EQUAL("", error.c_str());
  CHECK_TRUE(from_old == flightlog::binary_rows_to_csv(glb, error));
}
