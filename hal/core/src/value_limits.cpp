// SPDX-License-Identifier: Apache-2.0
#include "glider/config/value_limits.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace glider::config {

bool within(double value, const Range& range) {
  return std::isfinite(value) && value >= range.min && value <= range.max;
}

const Range& range_of(const std::vector<KeyRange>& table, std::string_view key) {
  for (const KeyRange& k : table) {
    if (key == k.key) return k.range;
  }
  throw std::logic_error("no range for " + std::string(key));
}

std::string show_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0.0 ? "inf" : "-inf";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

std::string show_range(const Range& range) {
  // Built by append: GCC 12 warns falsely (-Wrestrict, its bug 105651) on "literal" + std::string&&.
  std::string out("[");
  out.append(show_value(range.min)).append(", ").append(show_value(range.max)).append("]");
  if (range.unit != nullptr && range.unit[0] != '\0') out += std::string(" ") + range.unit;
  return out;
}

std::string range_problem(double value, const Range& range) {
  if (within(value, range)) return "";
  return "value " + show_value(value) + " is outside the allowed range " + show_range(range);
}

std::string shorten(std::string_view text, std::size_t max_chars) {
  if (text.size() <= max_chars) return std::string(text);
  return std::string(text.substr(0, max_chars)) + "... (" + std::to_string(text.size()) + " characters)";
}

std::optional<std::int64_t> whole_number(double value, std::int64_t lo, std::int64_t hi) {
  // Compared as doubles first: casting an out-of-range double is undefined.
  if (!(value >= static_cast<double>(lo) && value <= static_cast<double>(hi))) return std::nullopt;
  // 2^63 itself is representable but one past INT64_MAX: stay well inside.
  if (value != std::trunc(value) || !(std::fabs(value) < 9.0e18)) return std::nullopt;
  const auto integer = static_cast<std::int64_t>(value);
  if (integer < lo || integer > hi) return std::nullopt;
  return integer;
}

}  // namespace glider::config
