// SPDX-License-Identifier: Apache-2.0
#include "ascii_header.hpp"

#include <algorithm>
#include <charconv>
#include <unordered_set>
#include <vector>

namespace glider::slocum::detail {
namespace {

// A header line is short; a missing newline within this many bytes means
// the file is not text where a header should be.
constexpr std::size_t kMaxLine = 512;
// Real headers have 14 tags; more than this without num_ascii_tags is not a header.
constexpr std::size_t kMaxTags = 64;
constexpr int kEncodingVersion = 5;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::string printable(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, 40)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
  return out;
}

// The next line at `pos` (without its newline); `pos` moves past it.
std::string_view next_line(std::string_view bytes, std::size_t& pos, const std::string& source, const char* what) {
  const std::size_t end = bytes.find('\n', pos);
  if (end == std::string_view::npos) {
    throw SlocumError(source, pos, std::string("file ends inside the ") + what + " (truncated)");
  }
  if (end - pos > kMaxLine) {
    throw SlocumError(source, pos, "no end of line within " + std::to_string(kMaxLine) + " bytes in the " + what);
  }
  const std::string_view line = bytes.substr(pos, end - pos);
  pos = end + 1;
  return line;
}

template <typename T>
bool parse_number(std::string_view text, T& value) {
  text = trim(text);
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && ptr == text.data() + text.size();
}

std::size_t required_count(const Header& header, std::string_view key, const std::string& source) {
  const auto text = header.tag(key);
  std::size_t value = 0;
  if (!text) throw SlocumError(source, 0, "header has no '" + std::string(key) + "' tag");
  if (!parse_number(*text, value)) {
    throw SlocumError(source, 0, "header tag " + std::string(key) + ": '" + printable(*text) + "' is not a count");
  }
  return value;
}

}  // namespace

Header parse_header(std::string_view bytes, std::size_t& pos, const std::string& source) {
  if (bytes.empty()) throw SlocumError(source, 0, "empty file");
  Header header;
  std::size_t expected_tags = kMaxTags;
  while (header.tags.size() < expected_tags) {
    const std::size_t line_start = pos;
    const std::string_view line = next_line(bytes, pos, source, "ASCII header");
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos) {
      throw SlocumError(source, line_start, "header line without ':' ('" + printable(line) + "')");
    }
    const std::string key(trim(line.substr(0, colon)));
    const std::string value(trim(line.substr(colon + 1)));
    if (header.tags.empty() && key != "dbd_label") {
      throw SlocumError(source, 0, "not a DINKUM binary file: first line is '" + printable(line) + "', not dbd_label");
    }
    if (key == "num_ascii_tags") {
      if (!parse_number(value, expected_tags) || expected_tags < 2 || expected_tags > kMaxTags) {
        throw SlocumError(source, line_start,
                          "num_ascii_tags '" + printable(value) + "' is not 2.." + std::to_string(kMaxTags));
      }
    }
    header.tags.emplace_back(key, value);
  }
  if (expected_tags == kMaxTags && !header.tag("num_ascii_tags")) {
    throw SlocumError(source, 0, "header has no num_ascii_tags within " + std::to_string(kMaxTags) + " lines");
  }
  const auto version = header.tag("encoding_ver");
  if (!version || !parse_number(*version, header.encoding_version)) {
    throw SlocumError(source, 0, "header has no numeric encoding_ver");
  }
  if (header.encoding_version != kEncodingVersion) {
    throw SlocumError(source, 0,
                      "encoding version " + std::to_string(header.encoding_version) + ", only version " +
                          std::to_string(kEncodingVersion) + " is supported");
  }
  header.total_num_sensors = required_count(header, "total_num_sensors", source);
  header.sensors_per_cycle = required_count(header, "sensors_per_cycle", source);
  header.state_bytes_per_cycle = required_count(header, "state_bytes_per_cycle", source);
  const std::size_t factored = required_count(header, "sensor_list_factored", source);
  header.sensor_list_factored = factored == 1;
  if (factored > 1)
    throw SlocumError(source, 0, "sensor_list_factored is " + std::to_string(factored) + ", not 0 or 1");
  const auto crc = header.tag("sensor_list_crc");
  if (!crc || crc->empty()) throw SlocumError(source, 0, "header has no sensor_list_crc");
  for (const char c : *crc) {
    const bool hex = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
    if (!hex) throw SlocumError(source, 0, "sensor_list_crc '" + printable(*crc) + "' is not hexadecimal");
    header.sensor_list_crc += static_cast<char>(c >= 'A' && c <= 'F' ? c - 'A' + 'a' : c);
  }
  if (header.sensors_per_cycle == 0 || header.sensors_per_cycle > header.total_num_sensors) {
    throw SlocumError(source, 0,
                      "sensors_per_cycle " + std::to_string(header.sensors_per_cycle) +
                          " is not 1..total_num_sensors (" + std::to_string(header.total_num_sensors) + ")");
  }
  if (header.state_bytes_per_cycle != (header.sensors_per_cycle + 3) / 4) {
    throw SlocumError(source, 0,
                      "state_bytes_per_cycle " + std::to_string(header.state_bytes_per_cycle) + " does not hold " +
                          std::to_string(header.sensors_per_cycle) + " 2-bit states");
  }
  return header;
}

SensorList parse_sensor_list(std::string_view text, std::size_t& pos, const Header& header, const std::string& source) {
  SensorList sensors;
  std::unordered_set<std::string_view> names;  // views into `text`
  // A list line is at least 14 bytes: never reserve more than the text can hold.
  sensors.reserve(std::min(header.sensors_per_cycle, (text.size() - pos) / 14 + 1));
  for (std::size_t line_number = 0; line_number < header.total_num_sensors; ++line_number) {
    const std::size_t line_start = pos;
    const std::string_view line = next_line(text, pos, source, "sensor list");
    std::vector<std::string_view> words;
    for (std::size_t i = 0; i < line.size();) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      const std::size_t start = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
      if (i > start) words.push_back(line.substr(start, i - start));
    }
    long used_index = 0;
    int bytes = 0;
    if (words.size() < 6 || words[0] != "s:" || !parse_number(words[3], used_index) || !parse_number(words[4], bytes)) {
      throw SlocumError(source, line_start,
                        "sensor list line " + std::to_string(line_number + 1) +
                            " is not 's: T|F index used_index "
                            "bytes name unit' ('" +
                            printable(line) + "')");
    }
    if (used_index < 0) continue;
    if (bytes != 1 && bytes != 2 && bytes != 4 && bytes != 8) {
      throw SlocumError(source, line_start,
                        "sensor " + std::string(words[5]) + ": " + std::to_string(bytes) + " bytes, not 1, 2, 4 or 8");
    }
    if (static_cast<std::size_t>(used_index) != sensors.size()) {
      throw SlocumError(source, line_start,
                        "sensor " + std::string(words[5]) + ": stored as number " + std::to_string(used_index) +
                            ", expected " + std::to_string(sensors.size()) + " (lines out of order)");
    }
    if (!names.insert(words[5]).second) {
      throw SlocumError(source, line_start, "sensor " + std::string(words[5]) + " is listed twice");
    }
    sensors.push_back(Sensor{std::string(words[5]), words.size() > 6 ? std::string(words[6]) : std::string(), bytes});
  }
  if (sensors.size() != header.sensors_per_cycle) {
    throw SlocumError(source, pos,
                      "sensor list has " + std::to_string(sensors.size()) +
                          " sensors stored per cycle, the header says " + std::to_string(header.sensors_per_cycle));
  }
  return sensors;
}

}  // namespace glider::slocum::detail
