// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstdint>
#include <span>

namespace glider::fw::comms {

// Zmodem's two checks. CRC-16 is CRC-16/XMODEM (poly 0x1021, init 0, sent
// high byte first); CRC-32 is the IEEE 802.3 one (reflected poly 0xEDB88320,
// init and final xor 0xFFFFFFFF, sent low byte first).
std::uint16_t crc16_update(std::uint16_t crc, std::uint8_t byte);
std::uint16_t crc16(std::span<const std::uint8_t> data, std::uint16_t crc = 0);

// Running register form (no final xor): start at kCrc32Init, finish with ~.
inline constexpr std::uint32_t kCrc32Init = 0xFFFFFFFFu;
// A register that ran over data and its own (complemented, little-endian)
// CRC ends at this residue.
inline constexpr std::uint32_t kCrc32Residue = 0xDEBB20E3u;
std::uint32_t crc32_update(std::uint32_t reg, std::uint8_t byte);
// The finished CRC-32 of data (as zlib's crc32()).
std::uint32_t crc32(std::span<const std::uint8_t> data);

}  // namespace glider::fw::comms
