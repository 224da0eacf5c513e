// SPDX-License-Identifier: Apache-2.0
#include <array>

#include "glider/firmware/comms/zmodem_crc.hpp"

namespace glider::fw::comms {
namespace {

// Tables built at compile time: a byte per lookup keeps a 300 KiB transfer's
// checks to a few hundred microseconds.
constexpr std::array<std::uint16_t, 256> make_crc16_table() {
  std::array<std::uint16_t, 256> table{};
  for (unsigned i = 0; i < 256; ++i) {
    auto crc = static_cast<std::uint16_t>(i << 8);
    for (int bit = 0; bit < 8; ++bit)
      crc = static_cast<std::uint16_t>((crc & 0x8000u) ? (crc << 1) ^ 0x1021u : (crc << 1));
    table[i] = crc;
  }
  return table;
}

constexpr std::array<std::uint32_t, 256> make_crc32_table() {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t i = 0; i < 256; ++i) {
    std::uint32_t crc = i;
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 1u) ? (crc >> 1) ^ 0xEDB88320u : (crc >> 1);
    table[i] = crc;
  }
  return table;
}

constexpr auto kCrc16Table = make_crc16_table();
constexpr auto kCrc32Table = make_crc32_table();

}  // namespace

std::uint16_t crc16_update(std::uint16_t crc, std::uint8_t byte) {
  return static_cast<std::uint16_t>((crc << 8) ^ kCrc16Table[((crc >> 8) ^ byte) & 0xFFu]);
}

std::uint16_t crc16(std::span<const std::uint8_t> data, std::uint16_t crc) {
  for (const std::uint8_t byte : data) crc = crc16_update(crc, byte);
  return crc;
}

std::uint32_t crc32_update(std::uint32_t reg, std::uint8_t byte) {
  return kCrc32Table[(reg ^ byte) & 0xFFu] ^ (reg >> 8);
}

std::uint32_t crc32(std::span<const std::uint8_t> data) {
  std::uint32_t reg = kCrc32Init;
  for (const std::uint8_t byte : data) reg = crc32_update(reg, byte);
  return ~reg;
}

}  // namespace glider::fw::comms
