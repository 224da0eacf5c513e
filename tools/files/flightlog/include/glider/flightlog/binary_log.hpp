// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading the flight log's binary form (glider/firmware/log/binary_rows.hpp,
// docs/flight-log.md "Binary logs"): read_flight_log() and
// parse_flight_log() accept it directly; glider-log-info --to-csv converts.
#include <string>
#include <string_view>

namespace glider::flightlog {

// True if `file` starts like a binary log (its second line is the encoding line).
bool is_binary_rows_log(std::string_view file);

// The CSV text of a binary log. A record cut short at the end (a killed
// writer) becomes a last line without its newline, which the reader drops
// and reports as torn; anything else that is not a record, and a block whose
// check record does not match its bytes (binary-rows-2), is an error
// (`error` says where, the text up to there is returned). `note`, if given,
// says what could not be checked: rows after the last check record (a cut
// file), or a whole binary-rows-1 file (written before the checks).
std::string binary_rows_to_csv(std::string_view file, std::string& error, std::string* note = nullptr);

// Converts the binary log at `path` to its CSV text at `csv_path`; "" on
// success, else what went wrong (naming the file).
std::string write_binary_rows_as_csv(const std::string& path, const std::string& csv_path);

}  // namespace glider::flightlog
