// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight log's compact binary form (docs/flight-log.md, "Binary logs"):
// the CSV log's own text lines (`# writer:`, metadata, header), then one
// record per row instead of its text, then the same `# end:` trailer line.
// The second line says the encoding:
//
//   # encoding: binary-rows-1
//
// A record is 'R', a 64-bit little-endian mask of the columns whose value
// changed since the previous record (all of them in the first), then the
// 8 little-endian bytes of each of those columns in column order: the time
// as signed microseconds, every other column as its double's bits. Writing
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

inline constexpr std::string_view kBinaryEncodingLine = "# encoding: binary-rows-1\n";
inline constexpr std::size_t kMaxBinaryColumns = 64;  // one bit each in the mask
inline constexpr std::size_t kMaxBinaryRecordBytes = 9 + 8 * kMaxBinaryColumns;

class BinaryRowEncoder {
 public:
  // Writes the record of a row of `count` columns (values[0], the time, is
  // not read: `time_us` is written) to `out`, which has room for
  // kMaxBinaryRecordBytes. Returns its length; 0 if count > kMaxBinaryColumns.
  std::size_t encode(hal::Micros time_us, const double* values, std::size_t count, char* out);

 private:
  std::array<std::uint64_t, kMaxBinaryColumns> last_{};
  bool first_ = true;
};

}  // namespace glider::fw
