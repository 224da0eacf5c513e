// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/binary_rows.hpp"

#include <bit>

#include "glider/firmware/comms/zmodem_crc.hpp"

namespace glider::fw {
namespace {

void put_u64(char* out, std::uint64_t value) {
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((value >> (8 * i)) & 0xFFu);
}

void put_u32(char* out, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((value >> (8 * i)) & 0xFFu);
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
  out[0] = kBinaryRecordTag;
  put_u64(out + 1, mask);
  cover_bytes(out, at);
  ++block_records_;
  return at;
}

void BinaryRowEncoder::cover(const char* text, std::size_t length) { cover_bytes(text, length); }

std::size_t BinaryRowEncoder::close_block(char* out) {
  out[0] = kBinaryCheckTag;
  put_u32(out + 1, block_records_);
  put_u32(out + 5, ~crc_register_);
  crc_register_ = comms::kCrc32Init;
  block_records_ = 0;
  return kBinaryCheckRecordBytes;
}

void BinaryRowEncoder::cover_bytes(const char* bytes, std::size_t length) {
  for (std::size_t i = 0; i < length; ++i) {
    crc_register_ = comms::crc32_update(crc_register_, static_cast<std::uint8_t>(bytes[i]));
  }
}

}  // namespace glider::fw
