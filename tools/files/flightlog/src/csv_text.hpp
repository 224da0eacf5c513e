// SPDX-License-Identifier: Apache-2.0
#pragma once
// Text-level pieces of the flight-log reader: lines, fields, numbers,
// metadata. Internal to glider_flightlog.
#include <charconv>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "glider/flightlog/flight_log.hpp"

namespace glider::flightlog {

// Spaces and tabs around a field or name. Hand-rolled because it runs once
// per field and find_first_not_of costs a fifth of the whole parse.
inline std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

inline bool is_blank(std::string_view line) { return trim(line).empty(); }

// Lines ended by \n or \r\n (files written on Windows), numbered from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}

  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }  // of the line last returned
  std::string_view rest() const { return pos_ < text_.size() ? text_.substr(pos_) : std::string_view{}; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t number_ = 0;
};

// Calls f(index, field) for each comma-separated field; returns the count.
// No quoting: the format has none (names and numbers only).
template <typename F>
std::size_t for_each_field(std::string_view line, F&& f) {
  std::size_t col = 0;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    f(col++, line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return col;
    start = comma + 1;
  }
}

enum class FieldStatus { kValue, kEmpty, kNotANumber, kOutOfRange, kInfinite };

// Empty or blank: no value (NaN). Otherwise the whole field must be a number
// as std::from_chars reads it (no leading '+'); it reads `nan`, `NaN` (any
// case) and `-nan` as NaN, which means no value too.
inline FieldStatus parse_field(std::string_view field, double& value) {
  field = trim(field);
  if (field.empty()) {
    value = std::numeric_limits<double>::quiet_NaN();
    return FieldStatus::kEmpty;
  }
  const char* last = field.data() + field.size();
  const auto [ptr, error] = std::from_chars(field.data(), last, value);
  if (error == std::errc::result_out_of_range) return FieldStatus::kOutOfRange;
  if (error != std::errc{} || ptr != last) return FieldStatus::kNotANumber;
  if (std::isinf(value)) return FieldStatus::kInfinite;
  return std::isnan(value) ? FieldStatus::kEmpty : FieldStatus::kValue;
}

// `# key: value`; nullopt for a comment without a key (no ':').
inline std::optional<MetadataEntry> parse_metadata(std::string_view line) {
  line.remove_prefix(1);  // '#'
  const std::size_t colon = line.find(':');
  if (colon == std::string_view::npos) return std::nullopt;
  const std::string_view key = trim(line.substr(0, colon));
  if (key.empty()) return std::nullopt;
  return MetadataEntry{std::string(key), std::string(trim(line.substr(colon + 1)))};
}

// Shortest text that reads back to the same double, for messages.
inline std::string format_number(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return {buffer, result.ptr};
}

}  // namespace glider::flightlog
