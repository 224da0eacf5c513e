// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight log's compact binary form (docs/flight-log.md, "Binary logs"):
// the CSV log's own text lines (`# writer:`, metadata, header), then one
// record per row instead of its text, then the same `# end:` trailer line.
// The second line says the encoding:
//
//   # encoding: binary-rows-2
//
// A record is 'R', a 64-bit little-endian mask of the columns whose value
// changed since the previous record (all of them in the first), then the
// 8 little-endian bytes of each of those columns in column order: the time
// as signed microseconds, every other column as its double's bits.
//
// The bytes come in checked blocks: a check record 'C', the block's record
// count (32-bit little-endian), and the CRC-32 (IEEE, as zlib's crc32) of
// every byte since the previous check record (the file's first byte for the
// first block: the text lines are covered too), 9 bytes. The writer closes a
// block at each flush and after the trailer line, so a finished file ends in
// a check record and a flipped bit anywhere is found (binary-rows-1 files,
// written before, have no check records and are read with a note). Writing
// one costs a comparison per column instead of a number's text per column;
// glider::flightlog::binary_rows_to_csv() turns a file back into the CSV log,
// byte for byte the one the CSV writer writes, and the flight-log reader does
// that itself, so every tool reads either form. One schema: the columns are
// the header's.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "glider/hal/time.hpp"

namespace glider::fw {

inline constexpr std::string_view kBinaryEncodingLine = "# encoding: binary-rows-2\n";
// The first encoding, without check records: still read, with a note.
inline constexpr std::string_view kBinaryEncodingLineUnchecked = "# encoding: binary-rows-1\n";
inline constexpr std::size_t kMaxBinaryColumns = 64;  // one bit each in the mask
inline constexpr std::size_t kMaxBinaryRecordBytes = 9 + 8 * kMaxBinaryColumns;
inline constexpr std::size_t kBinaryCheckRecordBytes = 9;  // 'C', u32 records, u32 CRC-32
inline constexpr char kBinaryRecordTag = 'R';
inline constexpr char kBinaryCheckTag = 'C';

class BinaryRowEncoder {
 public:
  // Writes the record of a row of `count` columns (values[0], the time, is
  // not read: `time_us` is written) to `out`, which has room for
  // kMaxBinaryRecordBytes. Returns its length; 0 if count > kMaxBinaryColumns.
  // The record also joins the open block's check.
  std::size_t encode(hal::Micros time_us, const double* values, std::size_t count, char* out);
  // Text the writer puts in the file between records (the header lines, the
  // trailer): covered by the open block's check like the records.
  void cover(const char* text, std::size_t length);
  // Writes the check record that closes the open block (kBinaryCheckRecordBytes
  // to `out`) and opens the next. Returns its length.
  std::size_t close_block(char* out);

 private:
  void cover_bytes(const char* bytes, std::size_t length);

  std::array<std::uint64_t, kMaxBinaryColumns> last_{};
  bool first_ = true;
  std::uint32_t crc_register_ = 0xFFFFFFFFu;  // running CRC-32 of the open block
  std::uint32_t block_records_ = 0;
};

}  // namespace glider::fw
