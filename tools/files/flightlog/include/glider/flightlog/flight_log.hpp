// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reading flight-log CSV files (the project's interchange format, see
// docs/flight-log.md): `# key: value` metadata, one header line, one row per
// sample, Slocum names and units. Every analysis tool reads logs through this.
//
// Storage is columnar: one std::vector<double> per column, NaN where the field
// was empty (or `nan`): "no new value in that cycle", never zero. Gaps are
// left as they are; gaps.hpp has the explicit, documented ways to fill them.
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "glider/config/value_limits.hpp"

namespace glider::flightlog {

using Column = std::vector<double>;

// "path:line:column_name: problem (column N)", with N the 1-based column
// index. Errors that concern the whole file (empty, no data rows) have no
// column: "path:line: problem". A field beyond the header's last column has
// no name: "path:line:(column N): problem".
class FlightLogError : public std::runtime_error {
 public:
  FlightLogError(std::string path, std::size_t line, std::string column_name, std::size_t column_index,
                 const std::string& problem);

  const std::string& path() const { return path_; }
  std::size_t line() const { return line_; }                  // 1-based; 0 when not about a line
  const std::string& column_name() const { return column_; }  // empty when not about a named column
  std::size_t column_index() const { return index_; }         // 1-based; 0 when not about one column

 private:
  std::string path_;
  std::size_t line_;
  std::string column_;
  std::size_t index_;
};

struct ReadOptions {
  // Strictly increasing time of each row; always required.
  std::string time_column = "m_present_time";
  // Each entry lists alternatives: the header must hold at least one of them.
  // The default is what the model-discrepancy analysis needs (contract table):
  // depth (or the CTD pressure), pitch and the buoyancy pump volume (deep
  // gliders log the pump as m_de_oil_vol, same sign).
  std::vector<std::vector<std::string>> required = {
      {"m_depth", "sci_water_pressure"}, {"m_pitch"}, {"m_ballast_pumped", "m_de_oil_vol"}};
  // Keep only these columns (plus the time and the required ones); the other
  // columns are skipped without being parsed. Empty: keep every column.
  std::vector<std::string> columns;
  // Header names read as other names, {from, to}: a log that is not in the
  // contract's names (e.g. gliderflight's "time", "pitch_rad") can still be
  // read, with every check applied under the contract's names.
  std::vector<std::pair<std::string, std::string>> rename;
};

struct MetadataEntry {
  std::string key;
  std::string value;
};

// How the log ends (docs/flight-log.md). Writers end a finished flight with
// one of these as the very last line:
//   # end: complete rows=<N> lost=<M>
//   # end: aborted <cause> rows=<N> lost=<M>
//   # end: stopped <reason> rows=<N> lost=<M>
// No trailer: the writer never finished (power cut, crash, kill -9, or a log
// from a writer without trailers). A last line without its newline is a row
// (or trailer) torn by the same: it is dropped, and said so.
struct LogEnd {
  enum class State { kNoTrailer, kComplete, kAborted, kStopped };
  State state = State::kNoTrailer;
  std::string cause;             // aborted's cause, stopped's reason
  std::size_t trailer_rows = 0;  // rows=<N> (writer's count)
  std::size_t trailer_lost = 0;  // lost=<M> (rows the writer could not write)
  std::size_t trailer_line = 0;  // 0 without a trailer
  std::size_t torn_line = 0;     // line of the dropped torn last line, 0 if none
  std::size_t torn_bytes = 0;    // its length
  // What of a binary log could not be checked (binary_rows_to_csv's note), "" if all.
  std::string unchecked;
  // The log names one of the project's writers (a '# writer: glider-...' line),
  // which always end a finished flight with a trailer. Logs converted from
  // elsewhere (Slocum .dbd, gliderflight) have none, and none is expected.
  bool trailer_expected = false;
  bool complete() const { return state == State::kComplete; }
  // Worth a warning: a flight of ours that did not finish, or any torn row.
  bool unfinished() const {
    return (trailer_expected && state == State::kNoTrailer) || torn_line != 0 || !unchecked.empty();
  }
  // One line for people: "complete: 120 rows, 0 lost", "no end trailer:
  // incomplete (crashed or cut) flight", + the torn row and any disagreement
  // between the trailer's count and the rows read.
  std::string describe(std::size_t rows_read) const;
};

class FlightLog {
 public:
  FlightLog(std::string source, std::vector<MetadataEntry> metadata, std::vector<std::string> names,
            std::vector<Column> columns, std::size_t time_index);

  const std::string& source() const { return source_; }
  std::size_t rows() const { return time().size(); }
  const Column& time() const { return columns_[time_index_]; }

  // Kept columns in header order (the time column included).
  const std::vector<std::string>& column_names() const { return names_; }
  bool has(std::string_view name) const { return find(name) != nullptr; }
  const Column* find(std::string_view name) const;  // nullptr if absent
  // Throws FlightLogError naming the log when the column is absent.
  const Column& column(std::string_view name) const;
  // Fraction of rows with a value (0 for an absent column).
  double fill_fraction(std::string_view name) const;

  // `# key: value` lines in file order (keys and values trimmed).
  const std::vector<MetadataEntry>& metadata() const { return metadata_; }
  // Value of the first entry with this key.
  std::optional<std::string> metadata_value(std::string_view key) const;
  // The `vehicle.KEY` entries with the prefix removed ("vehicle.name" ->
  // "name"), in file order: the nominal vehicle the log was recorded with.
  std::vector<MetadataEntry> vehicle_metadata() const;

  // The end trailer and any torn last line (see LogEnd).
  const LogEnd& end() const { return end_; }
  void set_end(LogEnd end) { end_ = std::move(end); }

 private:
  std::string source_;
  std::vector<MetadataEntry> metadata_;
  std::vector<std::string> names_;
  std::vector<Column> columns_;
  std::map<std::string, std::size_t, std::less<>> index_;
  std::size_t time_index_;
  LogEnd end_;
};

// Reads a log file; throws FlightLogError (see the class) on anything that
// breaks the contract: cannot open, no header, missing required column,
// duplicate column, a field that is not a number, a row with more or fewer
// fields than the header, time empty or not strictly increasing, no rows, a
// malformed end trailer or anything after it, and a physically impossible
// value in any column plausible_range() knows. A torn
// last line (no newline) is dropped and reported in FlightLog::end().
FlightLog read_flight_log(const std::filesystem::path& path, const ReadOptions& options = {});
// The same on text in memory; source_name stands for the path in errors.
FlightLog parse_flight_log(std::string_view text, const std::string& source_name, const ReadOptions& options = {});

// The physical range a column's values must lie in: one table
// (flight_log.cpp) for every column of the log schema (hal::kLogColumns) and
// the Slocum science columns; nullptr for the others (the SIL's extra columns,
// other Slocum sensors).
const config::Range* plausible_range(std::string_view column_name);

}  // namespace glider::flightlog
