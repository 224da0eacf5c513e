// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/binary_rows.hpp"

#include <bit>

namespace glider::fw {
namespace {

constexpr char kRecordTag = 'R';

void put_u64(char* out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((value >> (8 * i)) & 0xFFu);
}

}  // namespace

std::size_t BinaryRowEncoder::encode(hal::Micros time_us, const double* values, std::size_t count, char* out) {
  if (count > kMaxBinaryColumns) return 0;
  std::uint64_t mask = 0;
  std::size_t at = 9;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint64_t bits = i == 0 ? static_cast<std::uint64_t>(time_us) : std::bit_cast<std::uint64_t>(values[i]);
    if (!first_ && bits == last_[i]) continue;
    last_[i] = bits;
    mask |= std::uint64_t{1} << i;
    put_u64(out + at, bits);
    at += 8;
  }
  first_ = false;
  out[0] = kRecordTag;
  put_u64(out + 1, mask);
  return at;
}

}  // namespace glider::fw
