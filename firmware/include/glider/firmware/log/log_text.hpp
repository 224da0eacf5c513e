// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight log's text, the same in every writer (SIL CSV, target ring log):
// the header from the one schema (hal::kLogColumns), each row's firmware
// fields as the shortest round-trip number text (std::to_chars), and the
// trailer that marks a finished log. Formatting allocates nothing and never
// throws: the target's writer thread and the SIL call it per row.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "glider/hal/log_record.hpp"

namespace glider::fw {

// Room for one row of firmware fields (34 columns of at most 25 characters).
inline constexpr std::size_t kLogFieldsMaxChars = 1024;

// "m_present_time,m_depth,...,x_mission_complete" (no trailing comma or newline).
std::string log_header();

// Writes the firmware fields of `record`, m_present_time given as `time_us`
// (exact decimal seconds), each followed by ','. Returns the characters
// written, 0 if `capacity` is too small (nothing usable written).
std::size_t format_log_fields(const hal::FlightLogRecord& record, hal::Micros time_us, char* out, std::size_t capacity);

// The same for a row given as column values: `values[0..count)` in file
// order, the firmware's columns first (values[0], the time, is not read:
// `time_us` is written), any after them numbers. Used to turn a binary log
// back into its CSV text (binary_rows.hpp).
std::size_t format_log_values(hal::Micros time_us, const double* values, std::size_t count, char* out,
                              std::size_t capacity);

// The shortest round-trip text of `value` and a ',' (NaN or inf: the ',' alone).
// Returns the characters written, 0 if they do not fit.
std::size_t format_log_number(double value, char* out, std::size_t capacity);

// Formats rows with the same bytes as format_log_fields and
// format_log_number, for a writer that formats every row of a log in order
// (the SIL's CSV): it keeps each column's last value and text, and a value
// with the same bits as in the previous row (most columns of most rows:
// commands, counters, an idle servo, the water) is copied, not formatted
// again. Allocates nothing.
class LogRowFormatter {
 public:
  static constexpr std::size_t kMaxExtraColumns = 32;  // a writer's own columns after the firmware's

  // As format_log_fields.
  std::size_t fields(const hal::FlightLogRecord& record, hal::Micros time_us, char* out, std::size_t capacity);
  // As format_log_number, for the writer's extra column `column` (< kMaxExtraColumns).
  std::size_t number(std::size_t column, double value, char* out, std::size_t capacity);

 private:
  struct Memo {
    std::uint64_t bits = 0;
    std::uint8_t length = 0;  // 0: nothing remembered
    char text[31] = {};       // the number and its ','
  };
  static std::size_t remembered(Memo& memo, double value, char* out, std::size_t capacity);

  std::array<Memo, hal::kLogColumns.size()> firmware_{};
  std::array<Memo, kMaxExtraColumns> extra_{};
};

// How a log ended (the last line of a finished log, docs/flight-log.md):
//   # end: complete rows=N lost=M
//   # end: aborted <cause> rows=N lost=M     (cause: fw::cause_id, one word)
//   # end: stopped <reason> rows=N lost=M    (signal, max_sim_time, cycle_limit, ...)
// `outcome` is "complete", "aborted <cause>" or "stopped <reason>". Returns the
// line with its newline; 0-length result if it does not fit.
std::size_t format_log_trailer(std::string_view outcome, std::uint64_t rows, std::uint64_t lost, char* out,
                               std::size_t capacity);

}  // namespace glider::fw
