// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/log_text.hpp"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>

namespace glider::fw {
namespace {

// Appends `text` at out[at]; false if it does not fit.
bool put(char* out, std::size_t capacity, std::size_t& at, std::string_view text) {
  if (text.size() > capacity - at) return false;
  std::memcpy(out + at, text.data(), text.size());
  at += text.size();
  return true;
}

bool put_char(char* out, std::size_t capacity, std::size_t& at, char c) {
  if (at >= capacity) return false;
  out[at++] = c;
  return true;
}

bool put_integer(char* out, std::size_t capacity, std::size_t& at, long long value) {
  const auto result = std::to_chars(out + at, out + capacity, value);
  if (result.ec != std::errc{}) return false;
  at = static_cast<std::size_t>(result.ptr - out);
  return true;
}

// Microseconds as exact decimal seconds ("12.5", "3", "1732492800.25").
bool put_time(char* out, std::size_t capacity, std::size_t& at, hal::Micros us) {
  const bool negative = us < 0;
  const unsigned long long magnitude =
      negative ? 0ULL - static_cast<unsigned long long>(us) : static_cast<unsigned long long>(us);
  if (negative && !put_char(out, capacity, at, '-')) return false;
  if (!put_integer(out, capacity, at, static_cast<long long>(magnitude / hal::kMicrosPerSecond))) return false;
  unsigned long long fraction = magnitude % hal::kMicrosPerSecond;
  if (fraction == 0) return true;
  char digits[6];
  for (int i = 5; i >= 0; --i) {
    digits[i] = static_cast<char>('0' + fraction % 10);
    fraction /= 10;
  }
  std::size_t length = 6;
  while (length > 0 && digits[length - 1] == '0') --length;
  return put_char(out, capacity, at, '.') && put(out, capacity, at, std::string_view(digits, length));
}

}  // namespace

std::string log_header() {
  std::string header;
  for (const hal::LogColumn& column : hal::kLogColumns) {
    if (!header.empty()) header += ',';
    header += column.name;
  }
  return header;
}

std::size_t format_log_number(double value, char* out, std::size_t capacity) {
  std::size_t at = 0;
  if (std::isfinite(value)) {
    const auto result = std::to_chars(out, out + capacity, value);
    if (result.ec != std::errc{}) return 0;
    at = static_cast<std::size_t>(result.ptr - out);
  }
  return put_char(out, capacity, at, ',') ? at : 0;
}

namespace {

// The fields of a row of `count` columns (the firmware's first, in
// hal::kLogColumns order; any after them are numbers): `value(i)` is column
// i's value, `number(i, value, out, capacity)` writes a kNumber column as
// format_log_number does.
template <typename Value, typename NumberText>
std::size_t format_fields(hal::Micros time_us, std::size_t count, Value value, char* out, std::size_t capacity,
                          NumberText number) {
  std::size_t at = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const hal::LogColumnKind kind =
        i < hal::kLogColumns.size() ? hal::kLogColumns[i].kind : hal::LogColumnKind::kNumber;
    bool ok = true;
    switch (kind) {
      case hal::LogColumnKind::kTime:
        ok = put_time(out, capacity, at, time_us) && put_char(out, capacity, at, ',');
        break;
      case hal::LogColumnKind::kInteger:
        ok = put_integer(out, capacity, at, static_cast<long long>(value(i))) && put_char(out, capacity, at, ',');
        break;
      case hal::LogColumnKind::kNumber: {
        const std::size_t n = number(i, value(i), out + at, capacity - at);
        ok = n > 0;
        at += n;
        break;
      }
    }
    if (!ok) return 0;
  }
  return at;
}

std::size_t plain_number(std::size_t, double value, char* out, std::size_t capacity) {
  return format_log_number(value, out, capacity);
}

double record_value(const hal::FlightLogRecord& record, std::size_t column) {
  return hal::kLogColumns[column].value ? hal::kLogColumns[column].value(record) : 0.0;
}

}  // namespace

std::size_t format_log_fields(const hal::FlightLogRecord& record, hal::Micros time_us, char* out,
                              std::size_t capacity) {
  return format_fields(
      time_us, hal::kLogColumns.size(), [&](std::size_t i) { return record_value(record, i); }, out, capacity,
      plain_number);
}

std::size_t format_log_values(hal::Micros time_us, const double* values, std::size_t count, char* out,
                              std::size_t capacity) {
  return format_fields(
      time_us, count, [values](std::size_t i) { return values[i]; }, out, capacity, plain_number);
}

std::size_t LogRowFormatter::remembered(Memo& memo, double value, char* out, std::size_t capacity) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  if (memo.length > 0 && memo.bits == bits) {
    if (memo.length > capacity) return 0;
    std::memcpy(out, memo.text, memo.length);
    return memo.length;
  }
  const std::size_t n = format_log_number(value, out, capacity);
  if (n > 0 && n <= sizeof memo.text) {
    std::memcpy(memo.text, out, n);
    memo.length = static_cast<std::uint8_t>(n);
    memo.bits = bits;
  } else {
    memo.length = 0;
  }
  return n;
}

std::size_t LogRowFormatter::fields(const hal::FlightLogRecord& record, hal::Micros time_us, char* out,
                                    std::size_t capacity) {
  return format_fields(
      time_us, hal::kLogColumns.size(), [&](std::size_t i) { return record_value(record, i); }, out, capacity,
      [this](std::size_t i, double value, char* text, std::size_t room) {
        return remembered(firmware_[i], value, text, room);
      });
}

std::size_t LogRowFormatter::number(std::size_t column, double value, char* out, std::size_t capacity) {
  if (column >= extra_.size()) return format_log_number(value, out, capacity);
  return remembered(extra_[column], value, out, capacity);
}

std::size_t format_log_trailer(std::string_view outcome, std::uint64_t rows, std::uint64_t lost, char* out,
                               std::size_t capacity) {
  std::size_t at = 0;
  const bool ok = put(out, capacity, at, "# end: ") && put(out, capacity, at, outcome) &&
                  put(out, capacity, at, " rows=") && put_integer(out, capacity, at, static_cast<long long>(rows)) &&
                  put(out, capacity, at, " lost=") && put_integer(out, capacity, at, static_cast<long long>(lost)) &&
                  put_char(out, capacity, at, '\n');
  return ok ? at : 0;
}

}  // namespace glider::fw
