// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/zmodem_encoder.hpp"

#include <algorithm>
#include <cstring>

#include "glider/firmware/comms/zmodem_crc.hpp"

namespace glider::fw::comms::zmodem {
namespace {

// What lrzsz escapes by default: ZDLE, DLE, XON, XOFF (either parity), and a
// CR after '@' (the "@CR" sequence some networks (Telenet) eat). With
// escape_all, every control character of either parity (rz -e / ESCCTL).
bool needs_escape(std::uint8_t c, std::uint8_t last, bool escape_all) {
  switch (c) {
    case kDle:
    case 0x10:
    case 0x90:
    case kXon:
    case 0x91:
    case kXoff:
    case 0x93:
      return true;
    case 0x0d:
    case 0x8d:
      return escape_all || (last & 0x7Fu) == '@';
    default:
      return escape_all && (c & 0x60u) == 0;
  }
}

constexpr char kHexDigits[] = "0123456789abcdef";

}  // namespace

void Encoder::make_room(std::size_t n) {
  if (kCapacity - tail_ >= n) return;
  const std::size_t count = pending();
  if (head_ != 0 && count != 0) std::memmove(buffer_.data(), buffer_.data() + head_, count);
  head_ = 0;
  tail_ = count;
}

void Encoder::put(std::uint8_t byte) {
  // Callers check room() first; a byte that would overflow is dropped (the
  // peer then sees a CRC error and asks again) rather than written past the end.
  if (tail_ >= kCapacity) make_room(1);
  if (tail_ >= kCapacity) return;
  buffer_[tail_++] = byte;
  last_ = byte;
}

void Encoder::put_escaped(std::uint8_t byte) {
  if (needs_escape(byte, last_, escape_control_)) {
    put(kDle);
    put(static_cast<std::uint8_t>(byte ^ 0x40u));
  } else {
    put(byte);
  }
}

void Encoder::put_hex(std::uint8_t byte) {
  put(static_cast<std::uint8_t>(kHexDigits[byte >> 4]));
  put(static_cast<std::uint8_t>(kHexDigits[byte & 0x0Fu]));
}

void Encoder::hex_header(const Header& header) {
  make_room(kHeaderCost);
  put(kPad);
  put(kPad);
  put(kDle);
  put(kHex);
  const auto type = static_cast<std::uint8_t>(header.type);
  std::uint16_t crc = crc16_update(0, type);
  put_hex(type);
  for (const std::uint8_t byte : header.bytes) {
    put_hex(byte);
    crc = crc16_update(crc, byte);
  }
  put_hex(static_cast<std::uint8_t>(crc >> 8));
  put_hex(static_cast<std::uint8_t>(crc));
  put(0x0d);
  put(0x8a);
  // The specification's XON un-sticks a peer stopped by a stray XOFF; not
  // after ZACK or ZFIN, whose peer may already be reading its own data.
  if (header.type != Frame::ack && header.type != Frame::fin) put(kXon);
}

void Encoder::binary_header(const Header& header, bool crc32) {
  make_room(kHeaderCost);
  put(kPad);
  put(kDle);
  put(crc32 ? kBin32 : kBin16);
  const auto type = static_cast<std::uint8_t>(header.type);
  put_escaped(type);
  for (const std::uint8_t byte : header.bytes) put_escaped(byte);
  if (crc32) {
    std::uint32_t reg = crc32_update(kCrc32Init, type);
    for (const std::uint8_t byte : header.bytes) reg = crc32_update(reg, byte);
    reg = ~reg;
    for (int i = 0; i < 4; ++i) put_escaped(static_cast<std::uint8_t>(reg >> (8 * i)));
  } else {
    std::uint16_t crc = crc16_update(0, type);
    for (const std::uint8_t byte : header.bytes) crc = crc16_update(crc, byte);
    put_escaped(static_cast<std::uint8_t>(crc >> 8));
    put_escaped(static_cast<std::uint8_t>(crc));
  }
}

void Encoder::subpacket(std::span<const std::uint8_t> data, std::uint8_t end, bool crc32) {
  make_room(subpacket_cost(data.size()));
  for (const std::uint8_t byte : data) put_escaped(byte);
  put(kDle);
  put(end);
  if (crc32) {
    std::uint32_t reg = kCrc32Init;
    for (const std::uint8_t byte : data) reg = crc32_update(reg, byte);
    reg = ~crc32_update(reg, end);
    for (int i = 0; i < 4; ++i) put_escaped(static_cast<std::uint8_t>(reg >> (8 * i)));
  } else {
    const std::uint16_t crc = crc16_update(crc16(data), end);
    put_escaped(static_cast<std::uint8_t>(crc >> 8));
    put_escaped(static_cast<std::uint8_t>(crc));
  }
  if (end == kCrcW) put(kXon);
}

void Encoder::raw(std::span<const std::uint8_t> bytes) {
  make_room(bytes.size());
  for (const std::uint8_t byte : bytes) put(byte);
}

void Encoder::cancel_sequence() {
  static constexpr std::array<std::uint8_t, 16> kAbort = {kCan, kCan, kCan, kCan, kCan, kCan, kCan, kCan,
                                                          8,    8,    8,    8,    8,    8,    8,    8};
  discard();
  raw(kAbort);
}

std::size_t Encoder::flush(ByteStream& stream, std::size_t budget) {
  const std::size_t count = std::min(pending(), budget);
  if (count == 0) return 0;
  const std::size_t written = stream.write(std::span<const std::uint8_t>(buffer_.data() + head_, count));
  head_ += std::min(written, count);
  if (head_ == tail_) head_ = tail_ = 0;
  return written;
}

}  // namespace glider::fw::comms::zmodem
