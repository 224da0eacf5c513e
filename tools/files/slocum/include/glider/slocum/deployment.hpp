// SPDX-License-Identifier: Apache-2.0
#pragma once
// A deployment's binary files read as one flight log: files in segment order,
// flight and science files merged on the flight computer's time, with the
// conventions of the project's real-data CSVs (tests/data/real/README.md):
//   - one row per flight (dbd) cycle, time m_present_time, the first
//     (file-open) cycle of every file dropped, time strictly increasing;
//   - a value where the sensor was set that cycle (new or "same value"),
//     empty (NaN) where it was not: no forward fill;
//   - lat/lon sensors in NMEA ddmm.mmmm as stored, 69696969 (invalid) empty;
//   - sci_* from the science files on sci_m_present_time, linearly
//     interpolated onto the flight time only between samples < 30 s apart;
//     CTD records with sci_ctd41cp_timestamp <= 0 or P=T=C=0 dropped; the
//     flight computer's copies of sci_* are used only without science files;
//   - non-finite values (e.g. -inf "not computed") are empty, with a warning;
//   - a set of science files only has one row per science cycle, time
//     sci_m_present_time.
#include <filesystem>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/slocum/binary_file.hpp"

namespace glider::slocum {

struct DeploymentOptions {
  ReadOptions read;
  // Columns wanted (the time column is always there); empty: every sensor
  // with at least one value. Names not in any file are an error.
  std::vector<std::string> columns;
  // Leave out requested columns no file has, instead of throwing.
  bool skip_missing_columns = false;
  // Columns renamed {from, to} in the log (as flightlog::ReadOptions::rename).
  std::vector<std::pair<std::string, std::string>> rename;
  double science_max_gap_s = 30.0;
};

struct Deployment {
  flightlog::FlightLog log;
  std::vector<std::string> units;  // per log column
  std::vector<int> stored_bytes;   // per log column: 1, 2, 4 or 8 (0 for none)
  std::vector<std::string> files;  // files read, in the order used
  std::vector<Warning> warnings;   // files skipped, partial files, dropped rows...
};

// Expands directories (their data files, not recursive), glob patterns and
// plain paths into the data files, in segment order: the name's numbers
// (glider-year-day-mission-segment, or the 8.3 name's number) compared as
// numbers, flight before science for the same segment. Throws
// std::runtime_error for an input that is neither, or a set with no file.
std::vector<std::filesystem::path> deployment_files(const std::vector<std::string>& inputs);

// Reads every file (a file that cannot be read is skipped with a warning;
// the rest is still read) and merges them. Throws SlocumError when no file
// could be read, or flightlog::FlightLogError for a requested column that
// no file has.
Deployment read_deployment(const std::vector<std::filesystem::path>& files, const DeploymentOptions& options = {});

}  // namespace glider::slocum
