// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one check every number read from a file goes through before the
// vehicle or a tool acts on it: finite, and inside a stated physical range.
// Written as !(min <= v && v <= max) so NaN never passes. Loaders attach the
// place (file:line:column) and the key; this header says what is wrong.
//
// Use from a TOML loader: `doc.number("mission.dive_to_m", kDiveDepth)` with
// `constexpr Range kDiveDepth{0.5, 1200.0, "m"};` (toml_document.hpp). Use
// from any other reader: `if (auto p = range_problem(v, r); !p.empty()) ...`.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glider::config {

// Both ends included. `unit` is printed after the range ("" for none).
struct Range {
  double min;
  double max;
  const char* unit;
};

// One key of a file format and its range: each loader publishes its table
// so the bad-value test (tests/unit/test_value_limits.cpp) can try every key.
struct KeyRange {
  const char* key;
  Range range;
};

// The range of `key` in a loader's table (std::logic_error if absent: a
// programming error, the table and the reader disagree).
const Range& range_of(const std::vector<KeyRange>& table, std::string_view key);

// Finite and min <= value <= max.
bool within(double value, const Range& range);

// "" when within(value, range); else e.g.
// "value -1e+308 is outside the allowed range [-80, 80] deg".
std::string range_problem(double value, const Range& range);

// The value as it would be written back: shortest round-trip, "nan", "inf".
std::string show_value(double value);
// "[min, max] unit".
std::string show_range(const Range& range);

// Text echoed into a message, cut to max_chars with the full length noted,
// so a 10 MB field never ends up whole in an error.
std::string shorten(std::string_view text, std::size_t max_chars = 60);

// The integer a double holds when it is a whole number in [lo, hi]; nullopt
// for NaN, inf, fractions and anything that would overflow the conversion.
std::optional<std::int64_t> whole_number(double value, std::int64_t lo, std::int64_t hi);

}  // namespace glider::config
