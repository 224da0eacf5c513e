// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/firmware/comms/zmodem_protocol.hpp"

namespace glider::fw::comms::zmodem {

// Cuts the incoming byte stream into Zmodem headers and data subpackets, one
// byte at a time (so a step can stop anywhere). Checks every CRC; a damaged
// header or subpacket is reported as such, never passed on. After a header
// that carries data (ZFILE, ZDATA, ZSINIT, ZCOMMAND) it reads subpackets until
// one ends the frame (ZCRCE/ZCRCW) or one is damaged. Five CANs in a row are
// the peer's abort, wherever they come.
class Parser {
 public:
  enum class Event : std::uint8_t {
    none,
    header,         // header() is valid
    bad_header,     // a header's CRC or hex digits were wrong
    subpacket,      // data() and end() are valid, CRC checked
    bad_subpacket,  // CRC wrong, bad escape or too long: back to hunting
    cancelled,      // five CANs
  };

  // Raw control characters are dropped when the receiver asked for every
  // control character to be escaped (what arrives raw is line noise then).
  void set_drop_control(bool drop) { drop_control_ = drop; }
  Event feed(std::uint8_t byte);
  // Forget any partial header or subpacket (after a ZRPOS, say).
  void reset();

  const Header& header() const { return header_; }
  bool header_crc32() const { return header_crc32_; }
  std::span<const std::uint8_t> data() const { return {data_.data(), data_length_}; }
  std::uint8_t end() const { return end_; }
  bool in_data() const { return state_ == State::data || state_ == State::data_crc; }

 private:
  enum class State : std::uint8_t { hunt, pad, pad_dle, hex, binary, data, data_crc };
  // One escaped byte decoded: value, or a frame end marker, or nothing yet.
  enum class Decoded : std::uint8_t { pending, value, frame_end, invalid };
  Decoded decode(std::uint8_t byte, std::uint8_t& value);
  Event header_done();
  Event data_byte(std::uint8_t byte);
  Event crc_byte(std::uint8_t byte);

  State state_ = State::hunt;
  bool escaped_ = false;
  bool drop_control_ = false;
  int cans_ = 0;
  // Header being read: type + 4 bytes + up to 4 CRC bytes.
  std::array<std::uint8_t, 9> raw_header_{};
  std::size_t header_length_ = 0;
  std::size_t header_need_ = 0;
  bool header_crc32_ = false;
  bool hex_high_ = true;
  std::uint8_t hex_value_ = 0;
  Header header_;
  bool data_crc32_ = false;
  std::array<std::uint8_t, kMaxSubpacket> data_{};
  std::size_t data_length_ = 0;
  bool pending_restart_ = false;  // data() was handed out; the next byte starts anew
  std::uint8_t end_ = 0;
  std::array<std::uint8_t, 4> crc_bytes_{};
  std::size_t crc_length_ = 0;
};

}  // namespace glider::fw::comms::zmodem
