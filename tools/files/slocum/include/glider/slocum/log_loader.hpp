// SPDX-License-Identifier: Apache-2.0
#pragma once
// One entry point for the tools that take a flight log: a flight-log CSV, or
// a glider's own binary files (files, a directory, glob patterns; see
// deployment.hpp), read into the same FlightLog.
#include <filesystem>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/slocum/binary_file.hpp"

namespace glider::slocum {

struct LogSource {
  // One CSV file, or any number of binary files / directories / globs.
  std::vector<std::string> inputs;
  // Sensor-list cache directories for binary files (default: each file's
  // folder and its cac/).
  std::vector<std::filesystem::path> cache_dirs;
};

// True when the inputs are Slocum binaries rather than one CSV file.
bool is_binary_log(const std::vector<std::string>& inputs);

// Reads the log. For binaries, `options` applies as for a CSV: the time
// column must be options.time_column (the default m_present_time accepts
// sci_m_present_time for a set of science files alone), the required columns must be there (FlightLogError otherwise),
// `columns` limits what is kept, `rename` renames. Warnings about the
// binaries (damaged or skipped files, dropped values) go to `warnings`.
flightlog::FlightLog load_flight_log(const LogSource& source, const flightlog::ReadOptions& options,
                                     std::vector<Warning>* warnings = nullptr);

}  // namespace glider::slocum
