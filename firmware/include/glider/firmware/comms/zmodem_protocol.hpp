// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "glider/hal/time.hpp"

// Zmodem's wire constants (Chuck Forsberg, "ZMODEM - Efficient file transfer
// protocol", 1988; the names are the specification's) and the engine options.
namespace glider::fw::comms::zmodem {

inline constexpr std::uint8_t kPad = '*';    // ZPAD: a header starts with it
inline constexpr std::uint8_t kDle = 0x18;   // ZDLE: escape (also CAN)
inline constexpr std::uint8_t kCan = 0x18;   // five of them in a row abort
inline constexpr std::uint8_t kBin16 = 'A';  // ZBIN: binary header, CRC-16
inline constexpr std::uint8_t kHex = 'B';    // ZHEX: hex header, CRC-16
inline constexpr std::uint8_t kBin32 = 'C';  // ZBIN32: binary header, CRC-32
inline constexpr std::uint8_t kXon = 0x11;
inline constexpr std::uint8_t kXoff = 0x13;

// Subpacket ends (after ZDLE).
inline constexpr std::uint8_t kCrcE = 'h';  // end of frame, no reply wanted
inline constexpr std::uint8_t kCrcG = 'i';  // frame continues, no reply
inline constexpr std::uint8_t kCrcQ = 'j';  // frame continues, ZACK wanted
inline constexpr std::uint8_t kCrcW = 'k';  // end of frame, ZACK wanted
inline constexpr std::uint8_t kRub0 = 'l';  // escaped 0x7f
inline constexpr std::uint8_t kRub1 = 'm';  // escaped 0xff

enum class Frame : std::uint8_t {
  rqinit = 0,
  rinit = 1,
  sinit = 2,
  ack = 3,
  file = 4,
  skip = 5,
  nak = 6,
  abort = 7,
  fin = 8,
  rpos = 9,
  data = 10,
  eof = 11,
  ferr = 12,
  crc = 13,
  challenge = 14,
  compl_ = 15,
  can = 16,
  freecnt = 17,
  command = 18,
  stderr_ = 19,
};

// ZRINIT capability flags (ZF0).
inline constexpr std::uint8_t kCanFdx = 0x01;   // full duplex
inline constexpr std::uint8_t kCanOvio = 0x02;  // receives while writing to disk
inline constexpr std::uint8_t kCanFc32 = 0x20;  // CRC-32 headers and data
inline constexpr std::uint8_t kEscCtl = 0x40;   // wants every control char escaped
// ZSINIT flag (ZF0): the sender wants control characters escaped.
inline constexpr std::uint8_t kTEscCtl = 0x40;
// ZFILE conversion (ZF0).
inline constexpr std::uint8_t kConvBinary = 1;
inline constexpr std::uint8_t kConvResume = 3;

// A header's four data bytes: a little-endian position (ZP0..ZP3) or flags
// (ZF3..ZF0, ZF0 being the last byte).
struct Header {
  Frame type = Frame::rqinit;
  std::array<std::uint8_t, 4> bytes{};

  static Header at(Frame type, std::uint32_t position) {
    return Header{type,
                  {static_cast<std::uint8_t>(position), static_cast<std::uint8_t>(position >> 8),
                   static_cast<std::uint8_t>(position >> 16), static_cast<std::uint8_t>(position >> 24)}};
  }
  static Header flags(Frame type, std::uint8_t f0, std::uint8_t f1 = 0) { return Header{type, {0, 0, f1, f0}}; }
  std::uint32_t position() const {
    return static_cast<std::uint32_t>(bytes[0]) | (static_cast<std::uint32_t>(bytes[1]) << 8) |
           (static_cast<std::uint32_t>(bytes[2]) << 16) | (static_cast<std::uint32_t>(bytes[3]) << 24);
  }
  std::uint8_t f0() const { return bytes[3]; }
  std::uint8_t f1() const { return bytes[2]; }
};

// Largest subpacket the parser takes (lrzsz's 8 KiB blocks, `sz -8`); the
// sender itself never sends more than Options::max_block.
inline constexpr std::size_t kMaxSubpacket = 8192;
// Largest subpacket the sender sends (the specification's limit).
inline constexpr std::uint32_t kMaxBlock = 1024;
// Longest file name sent or accepted (a Slocum name is 8.3; a segment's long
// name is about 30 characters).
inline constexpr std::size_t kMaxName = 63;

struct Options {
  hal::Micros timeout_us = 10'000'000;  // silence before a header is repeated
  int max_retries = 10;                 // repeats of one request before giving up
  bool escape_control = false;          // escape every control character (rz -e)
  std::uint32_t window_bytes = 32768;   // sender: data sent ahead of the last ZACK
  std::uint32_t max_block = kMaxBlock;  // sender: largest subpacket (halved on errors, <= kMaxBlock)
  std::uint32_t min_block = 32;
};

enum class Status : std::uint8_t { idle, running, done, failed };
enum class Failure : std::uint8_t { none, timeout, cancelled, file_error, refused, too_many_errors };
const char* failure_name(Failure failure);

}  // namespace glider::fw::comms::zmodem
