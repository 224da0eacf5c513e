// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/flight_log.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>
#include <utility>

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
    while (lines_.next(line)) {
      if (is_blank(line)) continue;  // e.g. a trailing empty line
      if (line.front() == '#') fail(lines_.number(), "", kNone, "metadata line after the header");
      read_row(line);
    }
    if (columns_[time_slot_].empty()) fail(header_line_, "", kNone, "header only, no data rows");
    return FlightLog(source_, std::move(metadata_), std::move(kept_names_), std::move(columns_), time_slot_);
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
    for (std::size_t col = 0; col < header_.size(); ++col) {
      if (!wanted(header_[col])) continue;
      if (header_[col] == options_.time_column) {
        time_col_ = col;
        time_slot_ = columns_.size();
      }
      slot_[col] = columns_.size();
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
      if (slot_[col] != kSkip) columns_[slot_[col]].push_back(parse_checked(col, field));
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
  std::vector<std::size_t> slot_;  // per header column: index into columns_, or kSkip
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

FlightLog parse_flight_log(std::string_view text, const std::string& source_name, const ReadOptions& options) {
  // A UTF-8 byte order mark (spreadsheet exports) would glue onto the first name.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) text.remove_prefix(kByteOrderMark.size());
  return Parser(text, source_name, options).parse();
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
