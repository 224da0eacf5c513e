// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/zmodem_parser.hpp"

#include "glider/firmware/comms/zmodem_crc.hpp"

namespace glider::fw::comms::zmodem {
namespace {

int hex_digit(std::uint8_t byte) {
  const auto c = static_cast<std::uint8_t>(byte & 0x7Fu);  // lrzsz reads hex with the parity bit stripped
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool carries_data(Frame type) {
  return type == Frame::file || type == Frame::data || type == Frame::sinit || type == Frame::command;
}

bool ends_frame(std::uint8_t end) { return end == kCrcE || end == kCrcW; }

}  // namespace

void Parser::reset() {
  state_ = State::hunt;
  escaped_ = false;
  header_length_ = 0;
  data_length_ = 0;
  crc_length_ = 0;
}

Parser::Decoded Parser::decode(std::uint8_t byte, std::uint8_t& value) {
  if (!escaped_) {
    if (byte == kDle) {
      escaped_ = true;
      return Decoded::pending;
    }
    value = byte;
    return Decoded::value;
  }
  escaped_ = false;
  switch (byte) {
    case kCrcE:
    case kCrcG:
    case kCrcQ:
    case kCrcW:
      value = byte;
      return Decoded::frame_end;
    case kRub0:
      value = 0x7F;
      return Decoded::value;
    case kRub1:
      value = 0xFF;
      return Decoded::value;
    default:
      break;
  }
  if ((byte & 0x60u) == 0x40u) {
    value = static_cast<std::uint8_t>(byte ^ 0x40u);
    return Decoded::value;
  }
  return Decoded::invalid;
}

Parser::Event Parser::feed(std::uint8_t byte) {
  // The peer's abort: five CANs in a row. A valid stream never has two in a
  // row (a ZDLE inside data is itself escaped), so noise rarely fakes it.
  if (byte == kCan) {
    if (++cans_ >= 5) {
      cans_ = 0;
      reset();
      return Event::cancelled;
    }
  } else {
    cans_ = 0;
  }
  // Flow-control characters are always escaped by a Zmodem sender, so a raw
  // one is the link's own (or noise): skipped, as lrzsz does.
  const auto low7 = static_cast<std::uint8_t>(byte & 0x7Fu);
  if (low7 == kXon || low7 == kXoff) return Event::none;
  if (drop_control_ && (byte & 0x60u) == 0 && byte != kDle && state_ != State::hunt) return Event::none;

  switch (state_) {
    case State::hunt:
      if (byte == kPad) state_ = State::pad;
      return Event::none;
    case State::pad:
      if (byte == kDle) {
        state_ = State::pad_dle;
      } else if (byte != kPad) {
        state_ = State::hunt;
      }
      return Event::none;
    case State::pad_dle:
      header_length_ = 0;
      escaped_ = false;
      hex_high_ = true;
      if (byte == kBin16 || byte == kBin32) {
        header_crc32_ = byte == kBin32;
        header_need_ = header_crc32_ ? 9 : 7;
        state_ = State::binary;
      } else if (byte == kHex) {
        header_crc32_ = false;
        header_need_ = 7;
        state_ = State::hex;
      } else {
        state_ = byte == kPad ? State::pad : State::hunt;
      }
      return Event::none;
    case State::hex: {
      const int digit = hex_digit(byte);
      if (digit < 0) {
        state_ = State::hunt;
        return Event::bad_header;
      }
      if (hex_high_) {
        hex_value_ = static_cast<std::uint8_t>(digit << 4);
        hex_high_ = false;
        return Event::none;
      }
      hex_high_ = true;
      raw_header_[header_length_++] = static_cast<std::uint8_t>(hex_value_ | digit);
      return header_length_ == header_need_ ? header_done() : Event::none;
    }
    case State::binary: {
      std::uint8_t value = 0;
      const Decoded decoded = decode(byte, value);
      if (decoded == Decoded::pending) return Event::none;
      if (decoded != Decoded::value) {
        state_ = State::hunt;
        return Event::bad_header;
      }
      raw_header_[header_length_++] = value;
      return header_length_ == header_need_ ? header_done() : Event::none;
    }
    case State::data:
      return data_byte(byte);
    case State::data_crc:
      return crc_byte(byte);
  }
  return Event::none;
}

Parser::Event Parser::header_done() {
  bool good = false;
  if (header_crc32_) {
    std::uint32_t reg = kCrc32Init;
    for (std::size_t i = 0; i < 9; ++i) reg = crc32_update(reg, raw_header_[i]);
    good = reg == kCrc32Residue;
  } else {
    std::uint16_t crc = 0;
    for (std::size_t i = 0; i < 7; ++i) crc = crc16_update(crc, raw_header_[i]);
    good = crc == 0;
  }
  if (!good) {
    state_ = State::hunt;
    return Event::bad_header;
  }
  header_.type = static_cast<Frame>(raw_header_[0]);
  for (std::size_t i = 0; i < 4; ++i) header_.bytes[i] = raw_header_[i + 1];
  if (carries_data(header_.type)) {
    state_ = State::data;
    data_crc32_ = header_crc32_;
    data_length_ = 0;
    pending_restart_ = false;
    escaped_ = false;
  } else {
    state_ = State::hunt;
  }
  return Event::header;
}

Parser::Event Parser::data_byte(std::uint8_t byte) {
  if (pending_restart_) {
    pending_restart_ = false;
    data_length_ = 0;
  }
  std::uint8_t value = 0;
  const Decoded decoded = decode(byte, value);
  if (decoded == Decoded::pending) return Event::none;
  if (decoded == Decoded::invalid) {
    state_ = State::hunt;
    return Event::bad_subpacket;
  }
  if (decoded == Decoded::frame_end) {
    end_ = value;
    crc_length_ = 0;
    state_ = State::data_crc;
    return Event::none;
  }
  if (data_length_ >= data_.size()) {
    state_ = State::hunt;
    return Event::bad_subpacket;
  }
  data_[data_length_++] = value;
  return Event::none;
}

Parser::Event Parser::crc_byte(std::uint8_t byte) {
  std::uint8_t value = 0;
  const Decoded decoded = decode(byte, value);
  if (decoded == Decoded::pending) return Event::none;
  if (decoded != Decoded::value) {
    state_ = State::hunt;
    return Event::bad_subpacket;
  }
  crc_bytes_[crc_length_++] = value;
  if (crc_length_ < (data_crc32_ ? 4u : 2u)) return Event::none;
  bool good = false;
  if (data_crc32_) {
    std::uint32_t reg = kCrc32Init;
    for (std::size_t i = 0; i < data_length_; ++i) reg = crc32_update(reg, data_[i]);
    reg = crc32_update(reg, end_);
    for (const std::uint8_t c : crc_bytes_) reg = crc32_update(reg, c);
    good = reg == kCrc32Residue;
  } else {
    std::uint16_t crc = crc16(data());
    crc = crc16_update(crc, end_);
    crc = crc16_update(crc16_update(crc, crc_bytes_[0]), crc_bytes_[1]);
    good = crc == 0;
  }
  if (!good) {
    state_ = State::hunt;
    return Event::bad_subpacket;
  }
  // The caller reads data() now; the next data byte starts a new subpacket.
  state_ = ends_frame(end_) ? State::hunt : State::data;
  pending_restart_ = true;
  return Event::subpacket;
}

}  // namespace glider::fw::comms::zmodem
