// SPDX-License-Identifier: Apache-2.0
// The flight log's one schema (hal::kLogColumns): the table in
// docs/flight-log.md says the same columns, in the same order, with the same
// units; the header, the row text and the trailer every writer uses come from
// it; the reader's units too.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "glider/firmware/log/log_text.hpp"
#include "glider/flightlog/columns.hpp"
#include "glider/hal/log_record.hpp"
#include "glider/hal/sim_log_columns.hpp"
#include "glider/sil/csv_flight_log.hpp"

using namespace glider;

namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" `");
  const auto last = text.find_last_not_of(" `");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

// (column, unit) of the first table after `section` in the doc.
std::vector<std::pair<std::string, std::string>> documented_columns(const char* section = "The firmware's columns") {
  std::ifstream in(GLIDER_SOURCE_DIR "/docs/flight-log.md");
  std::vector<std::pair<std::string, std::string>> rows;
  bool in_section = false, in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.find(section) != std::string::npos) in_section = true;
    if (!in_section) continue;
    if (line.rfind("|", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    std::vector<std::string> cells;
    std::stringstream cells_text(line.substr(1));
    for (std::string cell; std::getline(cells_text, cell, '|');) cells.push_back(trim(cell));
    if (cells.size() < 2 || cells[0] == "column" || cells[0].rfind("---", 0) == 0) continue;
    rows.emplace_back(cells[0], cells[1]);
  }
  return rows;
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::string field;
  for (char c : text) {
    if (c == ',') {
      out.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(field);
  return out;
}

}  // namespace

TEST_GROUP(LogSchema){};

TEST(LogSchema, DocsTableIsTheSchema) {
  const auto documented = documented_columns();
  CHECK_EQUAL(hal::kLogColumns.size(), documented.size());
  for (std::size_t i = 0; i < documented.size(); ++i) {
    STRCMP_EQUAL(std::string(hal::kLogColumns[i].name).c_str(), documented[i].first.c_str());
    STRCMP_EQUAL(std::string(hal::kLogColumns[i].unit).c_str(), documented[i].second.c_str());
  }
}

TEST(LogSchema, DocsTableIsTheSilSchema) {
  const auto documented = documented_columns("The SIL's columns");
  CHECK_EQUAL(hal::kSimLogColumns.size(), documented.size());
  for (std::size_t i = 0; i < documented.size(); ++i) {
    STRCMP_EQUAL(std::string(hal::kSimLogColumns[i].name).c_str(), documented[i].first.c_str());
    STRCMP_EQUAL(std::string(hal::kSimLogColumns[i].unit).c_str(), documented[i].second.c_str());
    CHECK(hal::kSimLogColumns[i].kind == hal::LogColumnKind::kNumber);
  }
}

TEST(LogSchema, SilHeaderIsUnchanged) {
  // The SIL's columns were a string before they were a table: the header a SIL log
  // has always had, so logs written before and after read the same.
  STRCMP_EQUAL((fw::log_header() +
                ",sci_water_temp,sci_water_cond,sci_water_pressure,"
                "sim_east_m,sim_north_m,sim_depth_m,sim_heading_rad,sim_pitch_rad,sim_speed_m_s,sim_alpha_rad,"
                "sim_glide_path_rad,sim_horizontal_speed_m_s,sim_depth_rate_m_s,sim_net_buoyancy_kg,"
                "sim_ballast_pumped_cc,sim_battpos_in,sim_fin_rad,sim_yaw_rate_rad_s,sim_density_kg_m3,"
                "sim_u_water_m_s,sim_v_water_m_s,sim_w_water_m_s,sim_temperature_c,sim_practical_salinity")
                   .c_str(),
               sil::CsvFlightLog::header().c_str());
}

TEST(LogSchema, ReaderUnitsComeFromTheSchema) {
  for (const hal::LogColumn& column : hal::kLogColumns) {
    STRCMP_EQUAL(std::string(column.unit).c_str(), std::string(flightlog::unit_of(column.name)).c_str());
  }
  for (const hal::SimLogColumn& column : hal::kSimLogColumns) {
    STRCMP_EQUAL(std::string(column.unit).c_str(), std::string(flightlog::unit_of(column.name)).c_str());
  }
}

TEST(LogSchema, HeaderAndRowTextRoundTrip) {
  const std::vector<std::string> names = split(fw::log_header());
  CHECK_EQUAL(hal::kLogColumns.size(), names.size());
  hal::FlightLogRecord r;
  r.m_depth = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
  r.m_pitch = -1.0 / 3.0;
  r.m_roll = std::numeric_limits<double>::quiet_NaN();
  r.m_heading = std::numeric_limits<double>::infinity();
  r.m_battery = 1e-300;
  r.x_abort_cause = 6;
  r.m_leakdetect = -1;
  r.x_loop_overruns = 4000000000u;
  char text[fw::kLogFieldsMaxChars];
  const std::size_t n = fw::format_log_fields(r, 1'732'492'800'250'000, text, sizeof text);
  CHECK_TRUE(n > 0);
  CHECK_EQUAL(',', text[n - 1]);
  const std::vector<std::string> fields = split(std::string(text, n - 1));
  CHECK_EQUAL(names.size(), fields.size());
  STRCMP_EQUAL("1732492800.25", fields[0].c_str());
  for (std::size_t i = 1; i < fields.size(); ++i) {
    const hal::LogColumn& column = hal::kLogColumns[i];
    const double value = column.value(r);
    if (!std::isfinite(value)) {
      STRCMP_EQUAL("", fields[i].c_str());  // no valid value: an empty field
      continue;
    }
    CHECK_EQUAL(value, std::strtod(fields[i].c_str(), nullptr));  // exact: shortest round-trip text
    if (column.kind == hal::LogColumnKind::kInteger) CHECK_TRUE(fields[i].find_first_of(".e") == std::string::npos);
  }
  STRCMP_EQUAL("0.30000000000000004", fields[1].c_str());
  CHECK_EQUAL(0u, fw::format_log_fields(r, 0, text, 20));  // too small: nothing usable
}

TEST(LogSchema, Trailer) {
  char text[128];
  std::size_t n = fw::format_log_trailer("complete", 3000, 0, text, sizeof text);
  STRCMP_EQUAL("# end: complete rows=3000 lost=0\n", std::string(text, n).c_str());
  n = fw::format_log_trailer("aborted depth_sensor", 12, 3, text, sizeof text);
  STRCMP_EQUAL("# end: aborted depth_sensor rows=12 lost=3\n", std::string(text, n).c_str());
  CHECK_EQUAL(0u, fw::format_log_trailer("stopped signal", 1, 1, text, 10));
}

TEST(LogSchema, RowFormatterWritesTheSameBytes) {
  // The SIL's remembering formatter against the stateless one, row after
  // row: values repeated, changed, changed back, -0 after 0, NaN, and a
  // buffer too small for the remembered text.
  fw::LogRowFormatter formatter;
  hal::FlightLogRecord r;
  const double extras[] = {0.0, -0.0, 0.1 + 0.2, std::numeric_limits<double>::quiet_NaN(), 1e-300, 250.0};
  char expected[fw::kLogFieldsMaxChars];
  char actual[fw::kLogFieldsMaxChars];
  for (int row = 0; row < 40; ++row) {
    r.m_depth = row % 3 == 0 ? 12.5 : 0.1 * row;
    r.m_pitch = row % 2 == 0 ? 0.0 : -0.0;
    r.m_roll = row % 5 == 0 ? std::numeric_limits<double>::quiet_NaN() : -1.0 / 3.0;
    r.c_ballast_pumped = row < 20 ? -250.0 : 250.0;
    r.x_yo_count = row / 7;
    const auto time_us = static_cast<hal::Micros>(row) * 1'000'000 + 250'000;
    const std::size_t n = fw::format_log_fields(r, time_us, expected, sizeof expected);
    CHECK_EQUAL(n, formatter.fields(r, time_us, actual, sizeof actual));
    STRCMP_EQUAL(std::string(expected, n).c_str(), std::string(actual, n).c_str());
    const double extra = extras[static_cast<std::size_t>(row / 4) % std::size(extras)];
    const std::size_t m = fw::format_log_number(extra, expected, sizeof expected);
    CHECK_EQUAL(m, formatter.number(0, extra, actual, sizeof actual));
    STRCMP_EQUAL(std::string(expected, m).c_str(), std::string(actual, m).c_str());
  }
  // A remembered text that does not fit is refused as format_log_number refuses it.
  CHECK_EQUAL(0u, formatter.number(0, 250.0, actual, 2));
  CHECK_EQUAL(0u, formatter.fields(r, 0, actual, 20));
}
