// SPDX-License-Identifier: Apache-2.0
#pragma once
// A glider's data as health reads it: one segment per Slocum segment name
// (<glider>-<yyyy>-<ddd>-<mission>-<segment>), the flight file and its
// science file read together as one flight log; or one flight-log CSV per
// segment. The decimated files (.sbd/.tbd/.mbd/.nbd and LZ4 forms) store a
// value only when it changed, so the commands and the slow actuator readings
// are held (forward filled) within the segment before any analysis.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"

namespace glider::health {

// Bad input that stops the whole run (two gliders mixed, a duplicate, files
// out of order): the message names the file(s). Exit 1; the state file is
// left as it was.
class BadInput : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SegmentFiles {
  std::string name;                // the segment's name (file stem)
  std::vector<std::string> files;  // the files read for it (flight first)
  bool decimated = false;          // an .sbd/.tbd-like file: values stored on change only
  std::string fingerprint;         // names, sizes and modification times: a changed file is a new segment
};

// The segments in the inputs (CSV files, Slocum files, folders, globs), in
// the order given (folders: segment order by name). For each Slocum segment
// the most complete flight file present is used (.dbd before .mbd before
// .sbd) with its science file (.ebd / .nbd / .tbd); .csv conversions beside
// Slocum files are ignored. Throws BadInput for a segment given twice.
std::vector<SegmentFiles> find_segments(const std::vector<std::string>& inputs);

// The glider a segment's file names (<glider>-<yyyy>-...), if any.
std::optional<std::string> glider_of_file(const std::string& path);

struct LoadedSegment {
  SegmentFiles files;
  std::optional<flightlog::FlightLog> log;  // slow columns held (decimated files); none: `problem` says why
  std::optional<flightlog::FlightLog> raw;  // as read (the values as stored)
  std::string problem;
  std::vector<std::string> warnings;
  double start_s = 0.0, end_s = 0.0;  // first and last row time (the log's clock)
};

// Reads one segment (never throws: a file that cannot be read is the
// segment's problem).
LoadedSegment load_segment(const SegmentFiles& files, const std::vector<std::filesystem::path>& cache_dirs);

// Columns held between stored values in a decimated file (commands and
// readings that change in steps): forward filled, at most `max_age_s`; and
// m_heading filled between stored values on the shorter arc (30 s at most).
flightlog::FlightLog hold_slow_columns(const flightlog::FlightLog& log, double max_age_s);

}  // namespace glider::health
