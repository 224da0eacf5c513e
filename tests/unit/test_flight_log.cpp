// SPDX-License-Identifier: Apache-2.0
// The flight-log reader against the contract (docs/flight-log.md): values,
// empty fields, metadata, every error with its exact message, and the real
// Slocum logs in tests/data/real (facts from their README).
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <string>

#include "glider/flightlog/flight_log.hpp"

using glider::flightlog::FlightLog;
using glider::flightlog::FlightLogError;
using glider::flightlog::parse_flight_log;
using glider::flightlog::read_flight_log;
using glider::flightlog::ReadOptions;

namespace {

const std::string kRealDir = GLIDER_SOURCE_DIR "/tests/data/real/";

const std::string kGood =
    "# source: unit test\n"
    "# vehicle.name: test_glider\n"
    "# vehicle.mass.hull_kg: 6.9\n"
    "m_present_time,m_depth,m_pitch,m_ballast_pumped,x_extra\n"
    "10,1.5,-0.4,-230,7\n"
    "11,,nan,NaN,\n"
    "12.5,2.5,-0.41,,-1e-3\n";

// The header of kGood, on line 4 after 3 metadata lines.
const std::string kHeader = "# a: 1\n# b: 2\n# c: 3\nm_present_time,m_depth,m_pitch,m_ballast_pumped\n";

// The message a text produces ("" if it reads).
std::string error_of(const std::string& text, const ReadOptions& options = {}) {
  try {
    parse_flight_log(text, "bad.csv", options);
  } catch (const FlightLogError& error) {
    return error.what();
  }
  return "";
}

bool strictly_increasing(const std::vector<double>& t) {
  return std::adjacent_find(t.begin(), t.end(), [](double a, double b) { return !(b > a); }) == t.end();
}

std::size_t count_valid(const std::vector<double>& values) {
  return static_cast<std::size_t>(std::count_if(values.begin(), values.end(), [](double v) { return !std::isnan(v); }));
}

}  // namespace

TEST_GROUP(FlightLogReader){};

TEST(FlightLogReader, ReadsColumnsWithEmptyFieldsAsNaN) {
  const FlightLog log = parse_flight_log(kGood, "good.csv");
  STRCMP_EQUAL("good.csv", log.source().c_str());
  LONGS_EQUAL(3, log.rows());
  LONGS_EQUAL(5, log.column_names().size());
  DOUBLES_EQUAL(12.5, log.time()[2], 0.0);
  CHECK_TRUE(&log.time() == &log.column("m_present_time"));
  DOUBLES_EQUAL(1.5, log.column("m_depth")[0], 0.0);
  CHECK_TRUE(std::isnan(log.column("m_depth")[1]));  // empty field: no value, never zero
  DOUBLES_EQUAL(-0.41, log.column("m_pitch")[2], 0.0);
  DOUBLES_EQUAL(-230.0, log.column("m_ballast_pumped")[0], 0.0);
  // A column the contract does not know is kept too, for the tools that want it.
  CHECK_TRUE(log.has("x_extra"));
  DOUBLES_EQUAL(-0.001, log.column("x_extra")[2], 0.0);
  DOUBLES_EQUAL(2.0 / 3.0, log.fill_fraction("m_depth"), 1e-15);
  DOUBLES_EQUAL(0.0, log.fill_fraction("no_such_column"), 0.0);
  CHECK_TRUE(log.find("m_roll") == nullptr);
}

TEST(FlightLogReader, NanInAnySpellingIsAnEmptyField) {
  const FlightLog log = parse_flight_log(kHeader + "1,nan,NaN,NAN\n2,-nan, nan ,\n", "nan.csv");
  for (const char* name : {"m_depth", "m_pitch", "m_ballast_pumped"}) {
    for (double value : log.column(name)) CHECK_TRUE(std::isnan(value));
  }
}

TEST(FlightLogReader, BlanksAroundFieldsCrLfAndBlankLinesAreAccepted) {
  const FlightLog log = parse_flight_log(
      "# k: v\r\n\r\n m_present_time , m_depth,m_pitch,m_ballast_pumped\r\n1, 2 ,0.3,4\r\n\r\n", "crlf.csv");
  LONGS_EQUAL(1, log.rows());
  DOUBLES_EQUAL(2.0, log.column("m_depth")[0], 0.0);
  DOUBLES_EQUAL(4.0, log.column("m_ballast_pumped")[0], 0.0);
  STRCMP_EQUAL("v", log.metadata_value("k").value().c_str());
  // A spreadsheet's UTF-8 byte order mark is not part of the first name.
  CHECK_TRUE(parse_flight_log("\xEF\xBB\xBF" + kHeader.substr(kHeader.find("m_present")) + "1,2,0.3,4\n", "bom.csv")
                 .has("m_present_time"));
}

TEST(FlightLogReader, MetadataKeepsOrderAndFindsVehicleKeys) {
  const FlightLog log = parse_flight_log(
      "#   source :  SIL: lockstep  \n# a comment without a key\n# vehicle.name: we01\n# vehicle.mass.hull_kg: 6.9\n"
      "# source: second\n" +
          kHeader.substr(kHeader.find("m_present")) + "0,0,0,0\n",
      "meta.csv");
  LONGS_EQUAL(4, log.metadata().size());
  STRCMP_EQUAL("source", log.metadata()[0].key.c_str());
  STRCMP_EQUAL("SIL: lockstep", log.metadata()[0].value.c_str());               // split at the first ':'
  STRCMP_EQUAL("SIL: lockstep", log.metadata_value("source").value().c_str());  // the first one
  CHECK_FALSE(log.metadata_value("a comment without a key").has_value());
  const auto vehicle = log.vehicle_metadata();
  LONGS_EQUAL(2, vehicle.size());
  STRCMP_EQUAL("name", vehicle[0].key.c_str());
  STRCMP_EQUAL("we01", vehicle[0].value.c_str());
  STRCMP_EQUAL("mass.hull_kg", vehicle[1].key.c_str());
  STRCMP_EQUAL("6.9", vehicle[1].value.c_str());
}

TEST(FlightLogReader, MissingRequiredColumnNamesIt) {
  STRCMP_EQUAL("bad.csv:4:m_pitch: required column missing",
               error_of("# a: 1\n# b: 2\n# c: 3\nm_present_time,m_depth,m_ballast_pumped\n1,2,3\n").c_str());
  STRCMP_EQUAL("bad.csv:1:m_depth: required column missing (nor its alternative sci_water_pressure)",
               error_of("m_present_time,m_pitch,m_ballast_pumped\n1,2,3\n").c_str());
  STRCMP_EQUAL("bad.csv:1:m_present_time: time column missing",
               error_of("time,m_depth,m_pitch,m_ballast_pumped\n1,2,3,4\n").c_str());
}

TEST(FlightLogReader, DepthMayComeFromTheCtdPressureAndPumpFromOilVolume) {
  STRCMP_EQUAL("", error_of("m_present_time,sci_water_pressure,m_pitch,m_de_oil_vol\n1,2,0.3,4\n").c_str());
}

TEST(FlightLogReader, TextInANumberNamesLineAndColumn) {
  STRCMP_EQUAL("bad.csv:6:m_pitch: 'abc' is not a number (column 3)",
               error_of(kHeader + "1,2,0.3,4\n2,2,abc,4\n").c_str());
  STRCMP_EQUAL("bad.csv:5:m_depth: '1.5m' is not a number (column 2)", error_of(kHeader + "1,1.5m,3,4\n").c_str());
  STRCMP_EQUAL("bad.csv:5:m_depth: '+1.5' is not a number (column 2)", error_of(kHeader + "1,+1.5,3,4\n").c_str());
  STRCMP_EQUAL("bad.csv:5:m_ballast_pumped: '1e999' is out of the range of a double (column 4)",
               error_of(kHeader + "1,2,0.3,1e999\n").c_str());
  STRCMP_EQUAL("bad.csv:5:m_ballast_pumped: 'inf' is not a finite number (column 4)",
               error_of(kHeader + "1,2,0.3,inf\n").c_str());
}

TEST(FlightLogReader, TimeGoingBackwardsOrStandingStillIsAnError) {
  STRCMP_EQUAL("bad.csv:7:m_present_time: time goes backwards: 11.5 after 12 on line 6 (column 1)",
               error_of(kHeader + "10,0,0,0\n12,0,0,0\n11.5,0,0,0\n").c_str());
  STRCMP_EQUAL("bad.csv:7:m_present_time: time does not increase: 12 as on line 6 (column 1)",
               error_of(kHeader + "10,0,0,0\n12,0,0,0\n12,0,0,0\n").c_str());
  STRCMP_EQUAL("bad.csv:6:m_present_time: empty time field (column 1)",
               error_of(kHeader + "10,0,0,0\nnan,0,0,0\n").c_str());
}

TEST(FlightLogReader, EmptyFileHeaderOnlyAndNoHeaderAreErrors) {
  STRCMP_EQUAL("bad.csv:1: empty file, no header line", error_of("").c_str());
  STRCMP_EQUAL("bad.csv:1: empty file, no header line", error_of("\n\n").c_str());
  STRCMP_EQUAL("bad.csv:2: no header line after the metadata", error_of("# a: 1\n# b: 2\n\n").c_str());
  STRCMP_EQUAL("bad.csv:1: no header line after the metadata", error_of("#\n").c_str());
  STRCMP_EQUAL("bad.csv:4: header only, no data rows", error_of(kHeader).c_str());
  STRCMP_EQUAL("bad.csv:4: header only, no data rows", error_of(kHeader + "\n").c_str());
}

TEST(FlightLogReader, RowWithTooManyOrTooFewFieldsIsAnError) {
  STRCMP_EQUAL("bad.csv:6:(column 5): 5 fields, but the header has 4 columns",
               error_of(kHeader + "1,2,0.3,4\n2,2,0.3,4,\n").c_str());
  STRCMP_EQUAL("bad.csv:5:m_ballast_pumped: missing field: the row has 3 fields, the header has 4 columns (column 4)",
               error_of(kHeader + "1,2,0.3\n").c_str());
}

TEST(FlightLogReader, BadHeadersAndLateMetadataAreErrors) {
  STRCMP_EQUAL("bad.csv:1:m_depth: duplicate column name, first at column 2 (column 5)",
               error_of("m_present_time,m_depth,m_pitch,m_ballast_pumped,m_depth\n1,2,3,4,5\n").c_str());
  STRCMP_EQUAL("bad.csv:1:(column 3): empty column name",
               error_of("m_present_time,m_depth,,m_pitch,m_ballast_pumped\n1,2,3,4,5\n").c_str());
  STRCMP_EQUAL("bad.csv:6: metadata line after the header", error_of(kHeader + "1,2,0.3,4\n# late: 1\n").c_str());
}

TEST(FlightLogReader, ErrorCarriesItsParts) {
  try {
    parse_flight_log(kHeader + "1,2,x,4\n", "parts.csv");
    FAIL("no error");
  } catch (const FlightLogError& error) {
    STRCMP_EQUAL("parts.csv", error.path().c_str());
    LONGS_EQUAL(5, error.line());
    STRCMP_EQUAL("m_pitch", error.column_name().c_str());
    LONGS_EQUAL(3, error.column_index());
  }
  const FlightLog log = parse_flight_log(kGood, "good.csv");
  CHECK_THROWS(FlightLogError, log.column("m_roll"));
  try {
    (void)log.column("m_roll");
  } catch (const FlightLogError& error) {
    STRCMP_EQUAL("good.csv:m_roll: no such column in the log", error.what());
  }
}

TEST(FlightLogReader, FileErrorsNameThePath) {
  const std::string path = GLIDER_TEST_OUTPUT_DIR "/flightlog_bad.csv";
  std::ofstream(path) << kHeader << "1,2,0.3,4\n0.5,2,0.3,4\n";
  try {
    read_flight_log(path);
    FAIL("no error");
  } catch (const FlightLogError& error) {
    STRCMP_EQUAL((path + ":6:m_present_time: time goes backwards: 0.5 after 1 on line 5 (column 1)").c_str(),
                 error.what());
  }
  const std::string missing = GLIDER_TEST_OUTPUT_DIR "/no_such_log.csv";
  try {
    read_flight_log(missing);
    FAIL("no error");
  } catch (const FlightLogError& error) {
    STRCMP_EQUAL((missing + ": cannot open: No such file or directory").c_str(), error.what());
  }
}

TEST(FlightLogReader, OptionsChooseTimeRequiredAndKeptColumns) {
  ReadOptions options;
  options.time_column = "t";
  options.required = {{"p"}};
  const FlightLog log = parse_flight_log("t,p,q\n1,2,3\n2,3,4\n", "opt.csv", options);
  DOUBLES_EQUAL(2.0, log.time()[1], 0.0);
  STRCMP_EQUAL("bad.csv:1:r: required column missing", error_of("t,p,q\n1,2,3\n", {"t", {{"r"}}, {}, {}}).c_str());
  // Only the listed columns are kept; the others are not even parsed.
  options.columns = {"q"};
  const FlightLog some = parse_flight_log("t,p,q,notes\n1,2,3,free text\n", "opt.csv", options);
  LONGS_EQUAL(3, some.column_names().size());  // t (time), p (required), q (asked for)
  CHECK_FALSE(some.has("notes"));
}

// The five real logs, with the facts their README states.
TEST(FlightLogReader, ReadsEveryRealDbdLog) {
  struct Expected {
    const char* file;
    std::size_t rows;
    double span_h;
    std::size_t ballast_values;         // "same value" cycles are written, so nearly every row
    std::size_t water_velocity_values;  // once per surfacing
  };
  for (const Expected& e : {Expected{"comet-2016-174-05.csv", 3043, 4.13, 3043, 12},
                            Expected{"gpl-3.0-or-later/amadeus-2014-204-05-000.csv", 897, 1.20, 897, 3},
                            Expected{"comet-2019-222-02-154.csv", 2243, 2.83, 2242, 2},
                            Expected{"comet-2019-222-02-156.csv", 2263, 2.86, 2263, 2}}) {
    const FlightLog log = read_flight_log(kRealDir + e.file);
    LONGS_EQUAL(e.rows, log.rows());
    LONGS_EQUAL(26, log.column_names().size());
    LONGS_EQUAL(12, log.metadata().size());
    CHECK_TRUE(strictly_increasing(log.time()));
    DOUBLES_EQUAL(e.span_h, (log.time().back() - log.time().front()) / 3600.0, 0.005);
    LONGS_EQUAL(e.ballast_values, count_valid(log.column("m_ballast_pumped")));
    LONGS_EQUAL(e.water_velocity_values, count_valid(log.column("m_water_vx")));
    // GPS only at the surface: a few percent of the rows.
    const double gps = log.fill_fraction("m_gps_lat");
    CHECK(gps > 0.01 && gps < 0.07);
    CHECK_TRUE(log.metadata_value("source_commit").has_value());
    CHECK_TRUE(log.vehicle_metadata().empty());
  }
  const FlightLog comet = read_flight_log(kRealDir + "comet-2016-174-05.csv");
  DOUBLES_EQUAL(1466704271.77127, comet.time().front(), 0.0);
  LONGS_EQUAL(3004, count_valid(comet.column("sci_water_pressure")));  // empty at the surface
  CHECK(comet.metadata_value("source_commit")->find("0ad087b9") != std::string::npos);
}

TEST(FlightLogReader, ReadsTheGliderflightAdcpLogWithItsOwnColumns) {
  ReadOptions options;
  options.time_column = "time";
  options.required = {{"pressure_bar"}, {"pitch_rad"}, {"buoyancy_drive_cc"}};
  const FlightLog log = read_flight_log(kRealDir + "gliderflight-adcp.csv", options);
  LONGS_EQUAL(13140, log.rows());
  LONGS_EQUAL(6, log.column_names().size());
  LONGS_EQUAL(13, log.metadata().size());
  CHECK_TRUE(strictly_increasing(log.time()));
  const auto& u = log.column("u_adcp_m_s");
  LONGS_EQUAL(4034, count_valid(u));
  // std::fmin skips the empty samples (NaN).
  const double slowest =
      std::accumulate(u.begin(), u.end(), std::nan(""), [](double a, double b) { return std::fmin(a, b); });
  DOUBLES_EQUAL(0.140307, slowest, 0.0);
  // With the default options it is not an analysis log: no Slocum time.
  STRCMP_EQUAL((kRealDir + "gliderflight-adcp.csv:14:m_present_time: time column missing").c_str(),
               [] {
                 try {
                   read_flight_log(kRealDir + "gliderflight-adcp.csv");
                 } catch (const FlightLogError& error) {
                   return std::string(error.what());
                 }
                 return std::string();
               }()
                   .c_str());
}

TEST(FlightLogReader, RenamedColumnsAreCheckedUnderTheirNewNames) {
  ReadOptions options;
  options.rename = {{"time", "m_present_time"}, {"pitch_rad", "m_pitch"}};
  options.required = {{"m_pitch"}};
  const FlightLog log = parse_flight_log("time,pitch_rad\n1,-0.4\n2,-0.41\n", "renamed.csv", options);
  CHECK_TRUE(log.has("m_pitch"));
  CHECK_FALSE(log.has("pitch_rad"));
  DOUBLES_EQUAL(2.0, log.time()[1], 0.0);
  try {
    parse_flight_log("time,pitch_rad\n2,-0.4\n1,-0.41\n", "renamed.csv", options);
    FAIL("expected an error");
  } catch (const FlightLogError& error) {
    STRCMP_CONTAINS("renamed.csv:3:m_present_time: time goes backwards", error.what());
  }
}
