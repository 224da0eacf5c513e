// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/nmea.hpp"

#include <charconv>
#include <cmath>

namespace glider::hal_linux {
namespace {

std::optional<int> hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return std::nullopt;
}

bool printable(char c) { return c >= 0x20 && c <= 0x7e; }

}  // namespace

NmeaCheck check_nmea(std::string_view line, NmeaSentence& out) {
  out.count = 0;
  if (line.size() < 2 || line.front() != '$') return NmeaCheck::kMalformed;
  const std::size_t star = line.rfind('*');
  if (star == std::string_view::npos) return NmeaCheck::kNoChecksum;
  if (star + 3 != line.size()) return NmeaCheck::kMalformed;
  const auto high = hex_digit(line[star + 1]);
  const auto low = hex_digit(line[star + 2]);
  if (!high || !low) return NmeaCheck::kMalformed;
  const std::string_view body = line.substr(1, star - 1);
  unsigned sum = 0;
  for (const char c : body) {
    if (!printable(c) || c == '$' || c == '*') return NmeaCheck::kMalformed;
    sum ^= static_cast<unsigned char>(c);
  }
  if (sum != static_cast<unsigned>(*high * 16 + *low)) return NmeaCheck::kBadChecksum;
  std::size_t start = 0;
  while (true) {
    if (out.count == kMaxNmeaFields) return NmeaCheck::kMalformed;
    const std::size_t comma = body.find(',', start);
    out.fields[out.count++] = body.substr(start, comma == std::string_view::npos ? body.npos : comma - start);
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out.fields[0].empty() ? NmeaCheck::kMalformed : NmeaCheck::kOk;
}

std::optional<double> nmea_number(std::string_view field) {
  double value = 0.0;
  const char* last = field.data() + field.size();
  const auto [end, ec] = std::from_chars(field.data(), last, value, std::chars_format::fixed);
  if (field.empty() || ec != std::errc() || end != last || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> nmea_integer(std::string_view field) {
  int value = 0;
  const char* last = field.data() + field.size();
  const auto [end, ec] = std::from_chars(field.data(), last, value);
  if (field.empty() || ec != std::errc() || end != last) return std::nullopt;
  return value;
}

std::optional<double> nmea_coordinate(std::string_view value, std::string_view hemisphere, double max_degrees) {
  const auto raw = nmea_number(value);
  if (!raw || *raw < 0.0 || hemisphere.size() != 1) return std::nullopt;
  const double degrees = std::floor(*raw / 100.0);
  const double minutes = *raw - 100.0 * degrees;
  if (minutes >= 60.0) return std::nullopt;
  const double magnitude = degrees + minutes / 60.0;
  if (magnitude > max_degrees) return std::nullopt;
  const char h = hemisphere[0];
  const bool positive = max_degrees <= 90.0 ? h == 'N' : h == 'E';
  const bool negative = max_degrees <= 90.0 ? h == 'S' : h == 'W';
  if (!positive && !negative) return std::nullopt;
  return positive ? magnitude : -magnitude;
}

}  // namespace glider::hal_linux
