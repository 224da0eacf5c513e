// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/slocum_list.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace glider::fw {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string_view next_word(std::string_view& rest) {
  rest = trim(rest);
  std::size_t end = 0;
  while (end < rest.size() && !std::isspace(static_cast<unsigned char>(rest[end]))) ++end;
  const std::string_view word = rest.substr(0, end);
  rest.remove_prefix(end);
  return word;
}

std::string known_names() {
  std::string names;
  for (const SlocumSensor& sensor : kSlocumFlightSensors) {
    if (!names.empty()) names += ", ";
    names += sensor.name;
  }
  return names;
}

std::string where(std::string_view file, std::size_t line) {
  return std::string(file) + ":" + std::to_string(line) + ": ";
}

}  // namespace

std::size_t SlocumSelection::count() const {
  std::size_t n = 0;
  for (const bool in : logged) n += in ? 1 : 0;
  return n;
}

SlocumSelection all_slocum_sensors() {
  SlocumSelection all;
  all.logged.fill(true);
  return all;
}

SlocumListResult parse_slocum_list(std::string_view text, std::string_view file) {
  SlocumListResult result;
  std::array<std::size_t, kSlocumFlightSensorCount> listed_at{};
  std::size_t line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t end = text.find('\n');
    std::string_view line = text.substr(0, end);
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    line = line.substr(0, line.find('#'));
    std::string_view rest = line;
    const std::string_view name_text = next_word(rest);
    if (name_text.empty()) continue;
    std::string name(name_text);
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const auto index = slocum_flight_sensor(name);
    if (!index) {
      result.error = where(file, line_number) + "sensor '" + name +
                     "' is not one the firmware logs (known: " + known_names() + ")";
      return result;
    }
    if (listed_at[*index] != 0) {
      result.error = where(file, line_number) + "sensor '" + name + "' is listed twice (first at line " +
                     std::to_string(listed_at[*index]) + ")";
      return result;
    }
    listed_at[*index] = line_number;
    double interval = 0.0;
    const std::string_view number = next_word(rest);
    if (!number.empty()) {
      const auto parsed = std::from_chars(number.data(), number.data() + number.size(), interval);
      const bool whole = parsed.ec == std::errc{} && parsed.ptr == number.data() + number.size();
      if (!whole || !std::isfinite(interval) || interval < 0.0 || interval > kMaxSlocumDecimationS) {
        result.error = where(file, line_number) + "sensor " + name + ": decimation '" + std::string(number) +
                       "' is not a number of seconds in [0, " +
                       std::to_string(static_cast<int>(kMaxSlocumDecimationS)) + "]";
        return result;
      }
      if (*index == 0 && interval != 0.0) {
        result.error = where(file, line_number) + "sensor m_present_time: decimation '" + std::string(number) +
                       "' refused: the time is stored in every written cycle (allowed: 0 or none)";
        return result;
      }
    }
    const std::string_view extra = next_word(rest);
    if (!extra.empty()) {
      result.error = where(file, line_number) + "sensor " + name + ": unexpected '" + std::string(extra) +
                     "' after the decimation (a line is: name [seconds])";
      return result;
    }
    result.selection.logged[*index] = true;
    result.selection.interval_s[*index] = interval;
  }
  result.selection.logged[0] = true;  // m_present_time
  result.selection.interval_s[0] = 0.0;
  return result;
}

SlocumListResult read_slocum_list(const std::string& path) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (in == nullptr) return {{}, path + ": cannot open the sensor list"};
  std::string text;
  char chunk[4096];
  std::size_t n = 0;
  while ((n = std::fread(chunk, 1, sizeof chunk, in)) > 0) text.append(chunk, n);
  const bool failed = std::ferror(in) != 0;
  std::fclose(in);
  if (failed) return {{}, path + ": cannot read the sensor list"};
  return parse_slocum_list(text, path);
}

}  // namespace glider::fw
