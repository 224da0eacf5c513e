// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/flight_log.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "glider/config/value_limits.hpp"
#include "glider/flightlog/binary_log.hpp"

#include "csv_text.hpp"

namespace glider::flightlog {
namespace {

constexpr double kEmpty = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kNone = 0;  // "no line" / "no column" in FlightLogError

// Appended piece by piece: GCC 12 gives a false -Wrestrict warning on
// `message += ":" + std::to_string(line)` here.
std::string format_message(const std::string& path, std::size_t line, const std::string& column, std::size_t index,
                           const std::string& problem) {
  const std::string column_ref = "(column " + std::to_string(index) + ")";
  std::string message = path;
  if (line != kNone) message.append(":").append(std::to_string(line));
  if (!column.empty()) {
    message.append(":").append(column);
  } else if (index != kNone) {
    message.append(":").append(column_ref);
  }
  message.append(": ").append(problem);
  if (!column.empty() && index != kNone) message.append(" ").append(column_ref);
  return message;
}

// memchr is vectorized; std::count over chars is not, and took a tenth of
// the parse of a 20 MB log.
std::size_t count_lines(std::string_view text) {
  std::size_t lines = 1;
  const char* end = text.data() + text.size();
  for (const char* p = text.data(); p != end; ++lines) {
    p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (p == nullptr) break;
    ++p;
  }
  return lines;
}

constexpr std::string_view kTrailerPrefix = "# end:";

std::optional<std::size_t> count_field(std::string_view text, std::string_view key) {
  if (text.substr(0, key.size()) != key) return std::nullopt;
  text.remove_prefix(key.size());
  std::size_t value = 0;
  const auto [ptr, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || ptr != text.data() + text.size() || text.empty()) return std::nullopt;
  return value;
}

// "# end: complete rows=N lost=M", "# end: aborted CAUSE rows=N lost=M",
// "# end: stopped REASON rows=N lost=M"; nullopt if not exactly that.
std::optional<LogEnd> parse_trailer(std::string_view line) {
  line.remove_prefix(kTrailerPrefix.size());
  if (line.substr(0, 1) != " ") return std::nullopt;
  line.remove_prefix(1);
  const std::size_t rows_at = line.rfind(" rows=");
  const std::size_t lost_at = line.rfind(" lost=");
  if (rows_at == std::string_view::npos || lost_at == std::string_view::npos || lost_at < rows_at) return std::nullopt;
  const auto rows = count_field(line.substr(rows_at + 1, lost_at - rows_at - 1), "rows=");
  const auto lost = count_field(line.substr(lost_at + 1), "lost=");
  if (!rows || !lost) return std::nullopt;
  const std::string_view what = line.substr(0, rows_at);
  LogEnd end;
  end.trailer_rows = *rows;
  end.trailer_lost = *lost;
  const auto with_cause = [&what, &end](std::string_view keyword, LogEnd::State state) {
    if (what.substr(0, keyword.size()) != keyword || what.size() <= keyword.size() + 1 || what[keyword.size()] != ' ') {
      return false;
    }
    end.cause = std::string(what.substr(keyword.size() + 1));
    end.state = state;
    return !trim(end.cause).empty() && end.cause == trim(end.cause);
  };
  if (what == "complete") {
    end.state = LogEnd::State::kComplete;
  } else if (!with_cause("aborted", LogEnd::State::kAborted) && !with_cause("stopped", LogEnd::State::kStopped)) {
    return std::nullopt;
  }
  return end;
}

// One pass over the text: metadata, header, then rows straight into the
// column vectors. Fields of skipped columns are split off but never parsed.
class Parser {
 public:
  Parser(std::string_view text, const std::string& source, const ReadOptions& options)
      : lines_(text), source_(source), options_(options) {}

  FlightLog parse() {
    read_metadata_and_header();
    select_columns();
    std::string_view line;
    LogEnd end;
    while (lines_.next(line)) {
      if (is_blank(line)) continue;  // e.g. a trailing empty line
      if (end.trailer_line != kNone) fail(lines_.number(), "", kNone, "line after the end trailer");
      if (line.front() == '#') {
        if (line.substr(0, kTrailerPrefix.size()) != kTrailerPrefix) {
          fail(lines_.number(), "", kNone, "metadata line after the header");
        }
        const auto trailer = parse_trailer(line);
        if (!trailer) {
          fail(lines_.number(), "", kNone,
               "malformed end trailer '" + config::shorten(line) +
                   "' (expected '# end: complete|aborted <cause>|stopped <reason> rows=<N> lost=<M>')");
        }
        end = *trailer;
        end.trailer_line = lines_.number();
        continue;
      }
      read_row(line);
    }
    if (columns_[time_slot_].empty()) fail(header_line_, "", kNone, "header only, no data rows");
    FlightLog log(source_, std::move(metadata_), std::move(kept_names_), std::move(columns_), time_slot_);
    log.set_end(std::move(end));
    return log;
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& column, std::size_t index,
                         const std::string& problem) const {
    throw FlightLogError(source_, line, column, index, problem);
  }
  // About field `col` (0-based) of the current line.
  [[noreturn]] void fail_field(std::size_t col, const std::string& problem) const {
    fail(lines_.number(), col < header_.size() ? header_[col] : "", col + 1, problem);
  }

  void read_metadata_and_header() {
    std::string_view line;
    std::size_t last_comment = kNone;
    while (lines_.next(line)) {
      if (is_blank(line)) continue;
      if (line.front() != '#') {
        read_header(line);
        return;
      }
      last_comment = lines_.number();
      if (auto entry = parse_metadata(line)) metadata_.push_back(std::move(*entry));
    }
    if (last_comment == kNone) fail(1, "", kNone, "empty file, no header line");
    fail(last_comment, "", kNone, "no header line after the metadata");
  }

  void read_header(std::string_view line) {
    header_line_ = lines_.number();
    for_each_field(line, [this](std::size_t col, std::string_view field) {
      std::string name(trim(field));
      if (name.empty()) fail(header_line_, "", col + 1, "empty column name");
      for (const auto& [from, to] : options_.rename) {
        if (name == from) {
          name = to;
          break;
        }
      }
      const auto previous = std::find(header_.begin(), header_.end(), name);
      if (previous != header_.end()) {
        fail(header_line_, name, col + 1,
             "duplicate column name, first at column " + std::to_string(previous - header_.begin() + 1));
      }
      header_.push_back(name);
    });
  }

  bool in_header(std::string_view name) const {
    return std::find(header_.begin(), header_.end(), name) != header_.end();
  }

  void select_columns() {
    if (!in_header(options_.time_column)) fail(header_line_, options_.time_column, kNone, "time column missing");
    for (const auto& alternatives : options_.required) {
      if (alternatives.empty() || std::any_of(alternatives.begin(), alternatives.end(),
                                              [this](const std::string& name) { return in_header(name); })) {
        continue;
      }
      std::string problem = "required column missing";
      for (std::size_t i = 1; i < alternatives.size(); ++i) {
        problem += (i == 1 ? " (nor its alternative " : ", ") + alternatives[i];
      }
      if (alternatives.size() > 1) problem += ")";
      fail(header_line_, alternatives.front(), kNone, problem);
    }
    const auto wanted = [this](const std::string& name) {
      if (options_.columns.empty() || name == options_.time_column) return true;
      const auto listed = [&name](const std::vector<std::string>& names) {
        return std::find(names.begin(), names.end(), name) != names.end();
      };
      return listed(options_.columns) || std::any_of(options_.required.begin(), options_.required.end(), listed);
    };
    // One newline per row (at most): reserving avoids regrowing 30 vectors.
    const std::size_t expected_rows = count_lines(lines_.rest());
    slot_.assign(header_.size(), kSkip);
    plausible_.assign(header_.size(), nullptr);
    for (std::size_t col = 0; col < header_.size(); ++col) {
      if (!wanted(header_[col])) continue;
      if (header_[col] == options_.time_column) {
        time_col_ = col;
        time_slot_ = columns_.size();
      }
      slot_[col] = columns_.size();
      plausible_[col] = plausible_range(header_[col]);
      kept_names_.push_back(header_[col]);
      columns_.emplace_back().reserve(expected_rows);
    }
  }

  void read_row(std::string_view line) {
    const std::size_t fields = for_each_field(line, [this, line](std::size_t col, std::string_view field) {
      if (col >= header_.size()) {
        const auto count = std::count(line.begin(), line.end(), ',') + 1;
        fail_field(
            col, std::to_string(count) + " fields, but the header has " + std::to_string(header_.size()) + " columns");
      }
      if (slot_[col] == kSkip) return;
      const double value = parse_checked(col, field);
      const config::Range* range = plausible_[col];
      if (range != nullptr && !std::isnan(value) && !config::within(value, *range)) {
        fail_field(col, "implausible: " + config::range_problem(value, *range));
      }
      columns_[slot_[col]].push_back(value);
    });
    if (fields < header_.size()) {
      fail_field(fields, "missing field: the row has " + std::to_string(fields) + " fields, the header has " +
                             std::to_string(header_.size()) + " columns");
    }
    check_time();
  }

  double parse_checked(std::size_t col, std::string_view field) const {
    double value = kEmpty;
    switch (parse_field(field, value)) {
      case FieldStatus::kValue:
      case FieldStatus::kEmpty:
        return value;
      case FieldStatus::kOutOfRange:
        fail_field(col, "'" + std::string(trim(field)) + "' is out of the range of a double");
      case FieldStatus::kInfinite:
        fail_field(col, "'" + std::string(trim(field)) + "' is not a finite number");
      case FieldStatus::kNotANumber:
        break;
    }
    fail_field(col, "'" + std::string(trim(field)) + "' is not a number");
  }

  void check_time() {
    const double time = columns_[time_slot_].back();
    const std::size_t col = time_col_;
    if (std::isnan(time)) fail_field(col, "empty time field");
    if (previous_time_line_ != kNone && !(time > previous_time_)) {
      const std::string where = " on line " + std::to_string(previous_time_line_);
      if (time == previous_time_) {
        fail_field(col, "time does not increase: " + format_number(time) + " as" + where);
      }
      fail_field(col,
                 "time goes backwards: " + format_number(time) + " after " + format_number(previous_time_) + where);
    }
    previous_time_ = time;
    previous_time_line_ = lines_.number();
  }

  static constexpr std::size_t kSkip = std::numeric_limits<std::size_t>::max();

  LineReader lines_;
  const std::string& source_;
  const ReadOptions& options_;
  std::vector<MetadataEntry> metadata_;
  std::size_t header_line_ = kNone;
  std::vector<std::string> header_;
  std::vector<std::size_t> slot_;                // per header column: index into columns_, or kSkip
  std::vector<const config::Range*> plausible_;  // per header column: nullptr = not checked
  std::vector<std::string> kept_names_;
  std::vector<Column> columns_;
  std::size_t time_col_ = 0;   // in the header
  std::size_t time_slot_ = 0;  // in columns_
  double previous_time_ = 0.0;
  std::size_t previous_time_line_ = kNone;
};

}  // namespace

FlightLogError::FlightLogError(std::string path, std::size_t line, std::string column_name, std::size_t column_index,
                               const std::string& problem)
    : std::runtime_error(format_message(path, line, column_name, column_index, problem)),
      path_(std::move(path)),
      line_(line),
      column_(std::move(column_name)),
      index_(column_index) {}

FlightLog::FlightLog(std::string source, std::vector<MetadataEntry> metadata, std::vector<std::string> names,
                     std::vector<Column> columns, std::size_t time_index)
    : source_(std::move(source)),
      metadata_(std::move(metadata)),
      names_(std::move(names)),
      columns_(std::move(columns)),
      time_index_(time_index) {
  for (std::size_t i = 0; i < names_.size(); ++i) index_.emplace(names_[i], i);
}

const Column* FlightLog::find(std::string_view name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? nullptr : &columns_[it->second];
}

const Column& FlightLog::column(std::string_view name) const {
  if (const Column* found = find(name)) return *found;
  throw FlightLogError(source_, kNone, std::string(name), kNone, "no such column in the log");
}

double FlightLog::fill_fraction(std::string_view name) const {
  const Column* values = find(name);
  if (values == nullptr || values->empty()) return 0.0;
  const auto filled = std::count_if(values->begin(), values->end(), [](double v) { return !std::isnan(v); });
  return static_cast<double>(filled) / static_cast<double>(values->size());
}

std::optional<std::string> FlightLog::metadata_value(std::string_view key) const {
  const auto it =
      std::find_if(metadata_.begin(), metadata_.end(), [key](const MetadataEntry& e) { return e.key == key; });
  if (it == metadata_.end()) return std::nullopt;
  return it->value;
}

std::vector<MetadataEntry> FlightLog::vehicle_metadata() const {
  constexpr std::string_view kPrefix = "vehicle.";
  std::vector<MetadataEntry> out;
  for (const MetadataEntry& entry : metadata_) {
    if (entry.key.size() > kPrefix.size() && entry.key.compare(0, kPrefix.size(), kPrefix) == 0) {
      out.push_back({entry.key.substr(kPrefix.size()), entry.value});
    }
  }
  return out;
}

// One table, every column of the log schema (hal::kLogColumns, in its units)
// and the science columns of converted Slocum logs: wide physical bounds, a
// value outside is a corrupt log, never a glider (one 1e308 in
// m_ballast_pumped would otherwise move every fit without a word).
struct PlausibleColumn {
  std::string_view name;
  config::Range range;
};
constexpr config::Range kTime{0.0, 4102444800.0, "s (1970 to 2100)"};
constexpr config::Range kHeading{-12.567, 12.567, "rad (+-4 pi)"};
constexpr config::Range kAngle{-3.1416, 3.1416, "rad"};
constexpr config::Range kBallast{-5000.0, 5000.0, "cc"};
constexpr config::Range kBattpos{-10.0, 10.0, "in"};
constexpr config::Range kWaterSpeed{-10.0, 10.0, "m/s"};
constexpr config::Range kCount{-1.0, 1e12, "count"};
constexpr config::Range kEnum{-1.0, 1000.0, "enum"};
constexpr config::Range kLat{-9000.0, 9000.0, "ddmm.mmmm or deg"};
constexpr config::Range kLon{-18000.0, 18000.0, "ddmm.mmmm or deg"};
constexpr config::Range kDistance{-1e8, 1e8, "m"};
constexpr std::array kPlausibleColumns{
    PlausibleColumn{"m_present_time", kTime},
    PlausibleColumn{"sci_m_present_time", kTime},
    PlausibleColumn{"m_depth", {-50.0, 11000.0, "m"}},
    PlausibleColumn{"m_depth_rate", {-10.0, 10.0, "m/s"}},
    PlausibleColumn{"m_pitch", {-1.5708, 1.5708, "rad"}},
    PlausibleColumn{"m_roll", kAngle},
    PlausibleColumn{"m_heading", kHeading},
    PlausibleColumn{"m_ballast_pumped", kBallast},
    PlausibleColumn{"c_ballast_pumped", kBallast},
    PlausibleColumn{"m_battpos", kBattpos},
    PlausibleColumn{"c_battpos", kBattpos},
    PlausibleColumn{"c_pitch", kAngle},
    PlausibleColumn{"m_depth_state", {-10.0, 100.0, "enum"}},
    PlausibleColumn{"x_yo_count", kCount},
    PlausibleColumn{"x_abort_cause", kEnum},
    PlausibleColumn{"x_loop_overruns", kCount},
    PlausibleColumn{"c_heading", kHeading},
    PlausibleColumn{"m_fin", kAngle},
    PlausibleColumn{"c_fin", kAngle},
    PlausibleColumn{"m_gps_lat", kLat},
    PlausibleColumn{"m_gps_lon", kLon},
    PlausibleColumn{"m_gps_utc_s", kTime},
    PlausibleColumn{"m_lat", kLat},
    PlausibleColumn{"m_lon", kLon},
    PlausibleColumn{"m_water_vx", kWaterSpeed},
    PlausibleColumn{"m_water_vy", kWaterSpeed},
    PlausibleColumn{"m_leakdetect", {-10.0, 10000.0, "enum"}},
    PlausibleColumn{"m_coulomb_amphr_total", {-1e4, 1e5, "Ah"}},
    PlausibleColumn{"m_battery", {0.0, 100.0, "V"}},
    PlausibleColumn{"x_waypoint", kCount},
    PlausibleColumn{"x_waypoints_reached", kCount},
    PlausibleColumn{"x_segment", kCount},
    PlausibleColumn{"x_dr_error_m", kDistance},
    PlausibleColumn{"x_dr_distance_m", kDistance},
    PlausibleColumn{"x_mission_complete", {0.0, 1.0, "bool"}},
    PlausibleColumn{"sci_water_pressure", {-5.0, 1200.0, "bar"}},
    PlausibleColumn{"m_pressure", {-5.0, 1200.0, "bar"}},
    PlausibleColumn{"sci_water_temp", {-5.0, 60.0, "degC"}},
    PlausibleColumn{"sci_water_cond", {-1.0, 100.0, "S/m"}},
};

const config::Range* plausible_range(std::string_view column_name) {
  for (const PlausibleColumn& column : kPlausibleColumns) {
    if (column.name == column_name) return &column.range;
  }
  return nullptr;
}

std::string LogEnd::describe(std::size_t rows_read) const {
  std::string out;
  switch (state) {
    case State::kNoTrailer:
      out = trailer_expected ? "no end trailer: incomplete flight (the writer crashed or was cut off)"
                             : "no end trailer (none expected: the log does not name one of the project's writers)";
      break;
    case State::kComplete:
      out = "complete";
      break;
    case State::kAborted:
      out = "aborted (" + cause + ")";
      break;
    case State::kStopped:
      out = "stopped (" + cause + ")";
      break;
  }
  if (state != State::kNoTrailer) {
    out += ": trailer rows=" + std::to_string(trailer_rows) + " lost=" + std::to_string(trailer_lost);
    if (trailer_rows != rows_read) out += ", but " + std::to_string(rows_read) + " rows read";
  }
  if (torn_line != 0) {
    out += "; torn last line " + std::to_string(torn_line) + " (" + std::to_string(torn_bytes) +
           " bytes, no newline) dropped";
  }
  if (!unchecked.empty()) out += "; " + unchecked;
  return out;
}

FlightLog parse_flight_log(std::string_view text, const std::string& source_name, const ReadOptions& options) {
  // The SIL's binary log is read as the CSV text it stands for.
  std::string converted;
  std::string unchecked;
  if (is_binary_rows_log(text)) {
    std::string error;
    converted = binary_rows_to_csv(text, error, &unchecked);
    if (!error.empty()) throw FlightLogError(source_name, kNone, "", kNone, "binary log: " + error);
    text = converted;
  }
  // A UTF-8 byte order mark (spreadsheet exports) would glue onto the first name.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) text.remove_prefix(kByteOrderMark.size());
  // Writers end every line with a newline: a last line without one was cut
  // mid-write (power, disk full, kill -9). It is dropped, never half-read.
  LogEnd torn;
  const std::size_t last_newline = text.rfind('\n');
  const std::string_view tail = last_newline == std::string_view::npos ? text : text.substr(last_newline + 1);
  if (!is_blank(tail)) {
    torn.torn_line = last_newline == std::string_view::npos ? 1 : count_lines(text.substr(0, last_newline + 1));
    torn.torn_bytes = tail.size();
    text.remove_suffix(tail.size());
  }
  FlightLog log = Parser(text, source_name, options).parse();
  LogEnd end = log.end();
  const std::optional<std::string> writer = log.metadata_value("writer");
  end.trailer_expected = writer && writer->rfind("glider-", 0) == 0;
  if (torn.torn_line != 0) {
    end.torn_line = torn.torn_line;
    end.torn_bytes = torn.torn_bytes;
  }
  end.unchecked = std::move(unchecked);
  log.set_end(std::move(end));
  return log;
}

FlightLog read_flight_log(const std::filesystem::path& path, const ReadOptions& options) {
  const std::string source = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FlightLogError(source, kNone, "", kNone, std::string("cannot open: ") + std::strerror(errno));
  // The whole file at once (a day at 1 Hz is 20-40 MB), parsed in place. A
  // regular file is read straight into a string of its size, which takes a
  // third of the time of streaming it; a pipe (`<(zcat log.csv.gz)`) is streamed.
  std::string text;
  std::error_code error;
  const auto size = std::filesystem::is_regular_file(path, error) ? std::filesystem::file_size(path, error) : 0;
  if (size > 0 && !error) {
    text.resize(size);
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
  } else {
    std::ostringstream stream;
    stream << in.rdbuf();
    text = std::move(stream).str();
  }
  if (in.bad()) throw FlightLogError(source, kNone, "", kNone, "read error");
  return parse_flight_log(text, source, options);
}

}  // namespace glider::flightlog
