// SPDX-License-Identifier: Apache-2.0
#include "modbus_request.hpp"

namespace glider::sim_tools {
namespace {

std::size_t word_at(const std::uint8_t* p) { return (static_cast<std::size_t>(p[0]) << 8) | p[1]; }

constexpr int kIllegalFunction = 1;
constexpr int kIllegalDataValue = 3;
constexpr std::size_t kMaxReadRegisters = 125;   // Modbus application protocol 1.1b3, 6.3
constexpr std::size_t kMaxWriteRegisters = 123;  // 6.12

}  // namespace

std::size_t tcp_frame_size(const std::uint8_t* bytes, std::size_t available) {
  if (available < kMbapHeaderLength) return kFrameIncomplete;
  const std::size_t protocol = word_at(bytes + 2);
  const std::size_t length = word_at(bytes + 4);  // unit id + PDU
  if (protocol != 0 || length < 2 || length > kMaxTcpFrameLength - 6) return kFrameMalformed;
  const std::size_t size = 6 + length;
  return available >= size ? size : kFrameIncomplete;
}

int request_exception(const std::uint8_t* frame, std::size_t length) {
  const std::uint8_t* pdu = frame + kMbapHeaderLength;
  const std::size_t pdu_length = length - kMbapHeaderLength;
  switch (pdu[0]) {
    case 3:
    case 4: {
      if (pdu_length != 5) return kIllegalDataValue;
      const std::size_t count = word_at(pdu + 3);
      return count >= 1 && count <= kMaxReadRegisters ? 0 : kIllegalDataValue;
    }
    case 6:
      return pdu_length == 5 ? 0 : kIllegalDataValue;
    case 16: {
      if (pdu_length < 6) return kIllegalDataValue;
      const std::size_t count = word_at(pdu + 3);
      const bool fits = count >= 1 && count <= kMaxWriteRegisters && pdu[5] == 2 * count && pdu_length == 6 + 2 * count;
      return fits ? 0 : kIllegalDataValue;
    }
    default:
      return kIllegalFunction;
  }
}

std::vector<std::uint8_t> exception_reply(const std::uint8_t* frame, int code) {
  return {frame[0],
          frame[1],
          0,
          0,
          0,
          3,
          frame[6],
          static_cast<std::uint8_t>(frame[7] | 0x80),
          static_cast<std::uint8_t>(code)};
}

}  // namespace glider::sim_tools
