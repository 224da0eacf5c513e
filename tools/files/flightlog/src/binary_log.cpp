// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/binary_log.hpp"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "glider/firmware/comms/zmodem_crc.hpp"
#include "glider/firmware/log/binary_rows.hpp"
#include "glider/firmware/log/log_text.hpp"

namespace glider::flightlog {
namespace {

std::uint64_t get_u64(const char* in) {
  std::uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(in[i]);
  return value;
}

// Reads exactly 4 bytes (a check record's last field ends the file).
std::uint32_t get_u32(const char* in) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(in[i]);
  return value;
}

std::uint32_t crc32_of(std::string_view bytes) {
  return fw::comms::crc32({reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()});
}

std::string hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08x", value);
  return text;
}

// The open block of a binary-rows-2 file: where it starts, its records.
struct Block {
  std::size_t start = 0;
  std::uint32_t records = 0;
  std::size_t first_row = 1;  // 1-based row number of its first record
};

// Checks the check record at `at` against the block it closes; "" if it holds.
std::string check_block(std::string_view file, std::size_t at, const Block& block) {
  const std::uint32_t stored_records = get_u32(file.data() + at + 1);
  const std::uint32_t stored_crc = get_u32(file.data() + at + 5);
  const std::uint32_t crc = crc32_of(file.substr(block.start, at - block.start));
  if (stored_records == block.records && stored_crc == crc) return "";
  return "byte " + std::to_string(at) + ": the check record of bytes " + std::to_string(block.start) + ".." +
         std::to_string(at) + " (rows " + std::to_string(block.first_row) + ".." +
         std::to_string(block.first_row + block.records - 1) + ") does not match: " + std::to_string(stored_records) +
         " records, CRC-32 " + hex(stored_crc) + " stored; " + std::to_string(block.records) + " records, " + hex(crc) +
         " read: the file is damaged";
}

}  // namespace

bool is_binary_rows_log(std::string_view file) {
  const std::size_t first_end = file.find('\n');
  if (first_end == std::string_view::npos || file.substr(0, 1) != "#") return false;
  const std::string_view second = file.substr(first_end + 1, fw::kBinaryEncodingLine.size());
  return second == fw::kBinaryEncodingLine || second == fw::kBinaryEncodingLineUnchecked;
}

std::string binary_rows_to_csv(std::string_view file, std::string& error, std::string* note) {
  std::string csv;
  error.clear();
  if (note != nullptr) note->clear();
  bool checked = true;  // binary-rows-2: check records
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
    if (line == fw::kBinaryEncodingLineUnchecked) {
      checked = false;
      if (note != nullptr) *note = "binary-rows-1 (written before block checks): damage cannot be detected";
      continue;
    }
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
  Block block;  // the first covers the text lines too
  bool unchecked_trailer = false;
  while (at < file.size()) {
    if (file[at] == '#') {  // the trailer (and whatever follows it: the reader judges)
      if (!checked) {
        csv += file.substr(at);
        break;
      }
      // binary-rows-2: the trailer line, then the check of the last block.
      const std::size_t end = file.find('\n', at);
      const std::size_t after = end == std::string_view::npos ? file.size() : end + 1;
      if (after + fw::kBinaryCheckRecordBytes > file.size() || file[after] != fw::kBinaryCheckTag) {
        // Cut before its check: the trailer is not trusted (read as a torn line).
        csv += file.substr(at, end == std::string_view::npos ? std::string_view::npos : end - at);
        unchecked_trailer = true;
        break;
      }
      error = check_block(file, after, block);
      if (error.empty() && after + fw::kBinaryCheckRecordBytes != file.size()) {
        error = "byte " + std::to_string(after + fw::kBinaryCheckRecordBytes) + ": " +
                std::to_string(file.size() - after - fw::kBinaryCheckRecordBytes) +
                " bytes after the last check record";
      }
      if (error.empty()) csv += file.substr(at, after - at);
      return csv;
    }
    if (checked && file[at] == fw::kBinaryCheckTag) {
      if (file.size() - at < fw::kBinaryCheckRecordBytes) break;  // cut short: the block stays unchecked
      error = check_block(file, at, block);
      if (!error.empty()) return csv;
      at += fw::kBinaryCheckRecordBytes;
      block = Block{at, 0, block.first_row + block.records};
      continue;
    }
    if (file[at] != fw::kBinaryRecordTag) {
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
    ++block.records;
    const std::size_t n = fw::format_log_values(time_us, values.data(), columns, row.data(), row.size());
    if (n == 0) {
      error = "a row did not fit its buffer";
      return csv;
    }
    row[n - 1] = '\n';
    csv.append(row.data(), n);
  }
  if (checked && (block.records > 0 || unchecked_trailer) && note != nullptr) {
    *note = (block.records > 0 ? "rows " + std::to_string(block.first_row) + ".." +
                                     std::to_string(block.first_row + block.records - 1) +
                                     (unchecked_trailer ? " and the trailer" : "")
                               : std::string("the trailer")) +
            " (from byte " + std::to_string(block.start) +
            ") have no check record after them: unchecked (the file was cut short or is damaged)";
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
    return path + ": not a binary log (its second line is not '# encoding: binary-rows-2' or '-1')";
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
