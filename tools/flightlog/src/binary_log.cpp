// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/binary_log.hpp"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "glider/firmware/log/binary_rows.hpp"
#include "glider/firmware/log/log_text.hpp"

namespace glider::flightlog {
namespace {

constexpr char kRecordTag = 'R';

std::uint64_t get_u64(const char* in) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(in[i]);
  return value;
}

}  // namespace

bool is_binary_rows_log(std::string_view file) {
  const std::size_t first_end = file.find('\n');
  return first_end != std::string_view::npos && file.substr(0, 1) == "#" &&
         file.substr(first_end + 1, fw::kBinaryEncodingLine.size()) == fw::kBinaryEncodingLine;
}

std::string binary_rows_to_csv(std::string_view file, std::string& error) {
  std::string csv;
  error.clear();
  // The text lines up to and including the header, without the encoding line.
  std::size_t at = 0;
  std::size_t columns = 0;
  while (at < file.size()) {
    const std::size_t end = file.find('\n', at);
    if (end == std::string_view::npos) {
      error = "the header ends without a newline";
      return csv;
    }
    const std::string_view line = file.substr(at, end + 1 - at);
    at = end + 1;
    if (line == fw::kBinaryEncodingLine) continue;
    csv += line;
    if (line[0] != '#') {
      columns = 1 + static_cast<std::size_t>(std::count(line.begin(), line.end(), ','));
      break;
    }
  }
  if (columns == 0 || columns > fw::kMaxBinaryColumns) {
    error = columns == 0 ? "no header line" : "more columns than a binary record holds (64)";
    return csv;
  }
  std::vector<double> values(columns, 0.0);
  hal::Micros time_us = 0;
  std::vector<char> row(fw::kLogFieldsMaxChars + 32 * fw::kMaxBinaryColumns);
  while (at < file.size()) {
    if (file[at] == '#') {  // the trailer (and whatever follows it: the reader judges)
      csv += file.substr(at);
      break;
    }
    if (file[at] != kRecordTag) {
      error = "byte " + std::to_string(at) + ": not a record";
      return csv;
    }
    const std::size_t left = file.size() - at;
    if (left < 9 || left < 9 + 8 * static_cast<std::size_t>(std::popcount(get_u64(file.data() + at + 1)))) {
      csv += "(binary record cut short: " + std::to_string(left) + " bytes)";  // no newline: torn
      break;
    }
    const std::uint64_t mask = get_u64(file.data() + at + 1);
    if (columns < 64 && (mask >> columns) != 0) {
      error = "byte " + std::to_string(at) + ": a record with more columns than the header";
      return csv;
    }
    std::size_t field = at + 9;
    for (std::size_t i = 0; i < columns; ++i) {
      if ((mask >> i & 1u) == 0) continue;
      const std::uint64_t bits = get_u64(file.data() + field);
      field += 8;
      if (i == 0) {
        time_us = static_cast<hal::Micros>(bits);
      } else {
        values[i] = std::bit_cast<double>(bits);
      }
    }
    at = field;
    const std::size_t n = fw::format_log_values(time_us, values.data(), columns, row.data(), row.size());
    if (n == 0) {
      error = "a row did not fit its buffer";
      return csv;
    }
    row[n - 1] = '\n';
    csv.append(row.data(), n);
  }
  return csv;
}

std::string write_binary_rows_as_csv(const std::string& path, const std::string& csv_path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return path + ": cannot open: " + std::strerror(errno);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  const std::string file = std::move(bytes).str();
  if (!is_binary_rows_log(file))
    return path + ": not a binary log (its second line is not '# encoding: binary-rows-1')";
  std::string error;
  const std::string csv = binary_rows_to_csv(file, error);
  if (!error.empty()) return path + ": " + error;
  std::ofstream out(csv_path, std::ios::binary | std::ios::trunc);
  out << csv;
  out.close();
  if (!out) return csv_path + ": cannot write";
  return "";
}

}  // namespace glider::flightlog
