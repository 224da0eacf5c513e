// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/firmware/comms/byte_stream.hpp"
#include "glider/firmware/comms/zmodem_protocol.hpp"

namespace glider::fw::comms::zmodem {

// Builds headers and subpackets (ZDLE-escaped, with their CRCs) into a fixed
// output buffer and drains it into the stream as the link takes it. Nothing
// here blocks: what does not fit stays queued for the next flush().
class Encoder {
 public:
  // Room for one largest subpacket escaped byte for byte, plus a few headers.
  static constexpr std::size_t kCapacity = 2 * 1024 + 512;

  void set_escape_control(bool all) { escape_control_ = all; }
  std::size_t pending() const { return tail_ - head_; }
  std::size_t room() const { return kCapacity - pending(); }
  // Worst-case bytes a subpacket of n data bytes takes.
  static constexpr std::size_t subpacket_cost(std::size_t n) { return 2 * n + 12; }
  static constexpr std::size_t kHeaderCost = 32;

  void hex_header(const Header& header);
  void binary_header(const Header& header, bool crc32);
  void subpacket(std::span<const std::uint8_t> data, std::uint8_t end, bool crc32);
  void raw(std::span<const std::uint8_t> bytes);
  // Cancels a session: 8 CAN then 8 backspaces (the specification's abort).
  void cancel_sequence();
  // Drops what has not been written yet (a ZRPOS makes it useless).
  void discard() { head_ = tail_ = 0; }
  // Writes at most `budget` queued bytes; returns how many the stream took.
  std::size_t flush(ByteStream& stream, std::size_t budget);

 private:
  void put(std::uint8_t byte);
  void put_escaped(std::uint8_t byte);
  void put_hex(std::uint8_t byte);
  void make_room(std::size_t n);

  std::array<std::uint8_t, kCapacity> buffer_{};
  std::size_t head_ = 0;
  std::size_t tail_ = 0;
  std::uint8_t last_ = 0;
  bool escape_control_ = false;
};

}  // namespace glider::fw::comms::zmodem
