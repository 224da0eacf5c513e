// SPDX-License-Identifier: Apache-2.0
// How a log ends: the end trailer, a torn last line, implausible values.
// The truncation test cuts a small log at every byte, as a power cut or a
// full disk could, and checks what the reader makes of each prefix.
#include <CppUTest/TestHarness.h>

#include <string>

#include "glider/flightlog/flight_log.hpp"
#include "glider/hal/log_record.hpp"

using glider::flightlog::FlightLogError;
using glider::flightlog::LogEnd;
using glider::flightlog::parse_flight_log;

namespace {

const std::string kHead =
    "# vehicle.name: we01\n"
    "m_present_time,m_depth,m_pitch,m_ballast_pumped\n";
const std::string kRows =
    "1000.0,0.5,-0.10,-250\n"
    "1001.0,1.2,-0.40,-250\n"
    "1002.0,2.4,-0.45,-250\n"
    "1003.0,3.9,-0.44,\n"
    "1004.0,5.1,-0.43,-250\n";

std::string error_of(const std::string& text) {
  try {
    parse_flight_log(text, "t.csv");
  } catch (const FlightLogError& error) {
    return error.what();
  }
  return "";
}

}  // namespace

TEST_GROUP(FlightLogEnd){};

TEST(FlightLogEnd, TrailersAreRead) {
  auto log = parse_flight_log(kHead + kRows + "# end: complete rows=5 lost=0\n", "t.csv");
  CHECK(log.end().complete());
  LONGS_EQUAL(5, log.end().trailer_rows);
  LONGS_EQUAL(8, log.end().trailer_line);
  STRCMP_EQUAL("complete: trailer rows=5 lost=0", log.end().describe(log.rows()).c_str());

  log = parse_flight_log(kHead + kRows + "# end: aborted overdepth rows=7 lost=2\n", "t.csv");
  CHECK(log.end().state == LogEnd::State::kAborted);
  STRCMP_EQUAL("overdepth", log.end().cause.c_str());
  LONGS_EQUAL(2, log.end().trailer_lost);
  STRCMP_EQUAL("aborted (overdepth): trailer rows=7 lost=2, but 5 rows read", log.end().describe(5).c_str());

  log = parse_flight_log(kHead + kRows + "# end: stopped time limit rows=5 lost=0\n", "t.csv");
  CHECK(log.end().state == LogEnd::State::kStopped);
  STRCMP_EQUAL("time limit", log.end().cause.c_str());

  // A log of one of our writers without its trailer did not finish.
  log = parse_flight_log("# writer: glider-sil\n" + kHead + kRows, "t.csv");
  CHECK(log.end().state == LogEnd::State::kNoTrailer);
  CHECK(log.end().trailer_expected);
  CHECK(log.end().unfinished());
  STRCMP_CONTAINS("no end trailer: incomplete flight", log.end().describe(5).c_str());

  // A log from elsewhere (converted Slocum files, gliderflight) never had one.
  log = parse_flight_log(kHead + kRows, "t.csv");
  CHECK(log.end().state == LogEnd::State::kNoTrailer);
  CHECK_FALSE(log.end().trailer_expected);
  CHECK_FALSE(log.end().unfinished());
  STRCMP_CONTAINS("none expected", log.end().describe(5).c_str());
}

TEST(FlightLogEnd, MalformedTrailerOrLinesAfterItAreRefusedWithTheLine) {
  for (const char* bad :
       {"# end: complete rows=5\n", "# end: complete rows=5 lost=-1\n", "# end: finished rows=5 lost=0\n",
        "# end: aborted rows=5 lost=0\n", "# end:complete rows=5 lost=0\n", "# end: complete rows=5 lost=0 extra\n",
        "# end: complete rows=1e3 lost=0\n"}) {
    STRCMP_CONTAINS("t.csv:8: malformed end trailer", error_of(kHead + kRows + bad).c_str());
  }
  STRCMP_CONTAINS("t.csv:9: line after the end trailer",
                  error_of(kHead + kRows + "# end: complete rows=5 lost=0\n1005.0,6,-0.4,-250\n").c_str());
}

TEST(FlightLogEnd, ImplausibleValuesAreRefusedWithFileAndLine) {
  STRCMP_EQUAL("t.csv:4:m_depth: implausible: value 1e+308 is outside the allowed range [-50, 11000] m (column 2)",
               error_of(kHead + "1000.0,0.5,-0.1,-250\n1001.0,1e308,-0.4,-250\n").c_str());
  STRCMP_CONTAINS("t.csv:3:m_present_time: implausible: value 1e+300",
                  error_of(kHead + "1e300,0.5,-0.1,-250\n").c_str());
  STRCMP_CONTAINS("t.csv:3:m_pitch: implausible: value -7", error_of(kHead + "1000,0.5,-7,-250\n").c_str());
  // Issue 28: one 1e308 in m_ballast_pumped moved diagnose's RMS without a word.
  STRCMP_EQUAL(
      "t.csv:5:m_ballast_pumped: implausible: value 1e+308 is outside the allowed range [-5000, 5000] cc (column 4)",
      error_of(kHead + "1000.0,0.5,-0.1,-250\n1001.0,1,-0.4,-250\n1002.0,2,-0.4,1e308\n").c_str());
}

// The plausibility table covers every column of the one log schema, in its
// units, and holds what the firmware writes at rest (zeros, except time).
TEST(FlightLogEnd, EveryLogSchemaColumnHasAPlausibleRange) {
  for (const glider::hal::LogColumn& column : glider::hal::kLogColumns) {
    const glider::config::Range* range = glider::flightlog::plausible_range(column.name);
    CHECK_TEXT(range != nullptr, std::string(column.name).c_str());
    CHECK_TEXT(range->min < range->max, std::string(column.name).c_str());
    if (column.name != "m_present_time")
      CHECK_TEXT(range->min <= 0.0 && 0.0 <= range->max, std::string(column.name).c_str());
  }
}

// Every prefix of a small log, as a cut at that byte leaves it: either a
// clear refusal (nothing readable yet) or the whole rows before the cut, the
// torn remainder dropped and reported, and "complete" only with the whole
// trailer and its newline.
TEST(FlightLogEnd, TruncatedAtEveryByte) {
  const std::string full = kHead + kRows + "# end: complete rows=5 lost=0\n";
  const std::size_t rows_start = kHead.size();
  int refused = 0, read = 0, torn = 0;
  for (std::size_t cut = 0; cut <= full.size(); ++cut) {
    const std::string prefix = full.substr(0, cut);
    // Whole rows in the prefix: newlines after the header.
    std::size_t whole_rows = 0;
    for (std::size_t i = rows_start; i < cut && i < rows_start + kRows.size(); ++i) whole_rows += full[i] == '\n';
    const bool ends_mid_line = cut > 0 && prefix.back() != '\n';
    try {
      const auto log = parse_flight_log(prefix, "t.csv");
      ++read;
      CHECK_TEXT(whole_rows >= 1, ("read with no whole row, cut " + std::to_string(cut)).c_str());
      LONGS_EQUAL_TEXT(whole_rows, log.rows(), ("cut at byte " + std::to_string(cut)).c_str());
      CHECK_EQUAL(ends_mid_line, log.end().torn_line != 0);
      torn += ends_mid_line ? 1 : 0;
      CHECK_EQUAL(cut == full.size(), log.end().complete());
      if (ends_mid_line) STRCMP_CONTAINS("dropped", log.end().describe(log.rows()).c_str());
    } catch (const FlightLogError& error) {
      ++refused;
      // Refused only while no whole row has been written.
      CHECK_TEXT(whole_rows == 0, (std::to_string(cut) + ": " + error.what()).c_str());
    }
  }
  LONGS_EQUAL(full.size() + 1, refused + read);
  CHECK(torn > 100);
}
