// SPDX-License-Identifier: Apache-2.0
#include "garbled_reply.hpp"

#include <modbus/modbus.h>

namespace glider::sim_tools {
namespace {

std::uint16_t crc16_modbus(const std::vector<std::uint8_t>& bytes) {
  std::uint16_t crc = 0xFFFF;
  for (const std::uint8_t byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit)
      crc = (crc & 1u) != 0 ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001u) : crc >> 1;
  }
  return crc;
}

int word_at(const std::uint8_t* p) { return (p[0] << 8) | p[1]; }

}  // namespace

std::vector<std::uint8_t> garbled_reply(const std::uint8_t* query, int header_length, bool rtu,
                                        const std::uint16_t* registers, int register_count) {
  const std::uint8_t* pdu = query + header_length;
  std::vector<std::uint8_t> reply_pdu;
  if (pdu[0] == MODBUS_FC_READ_HOLDING_REGISTERS) {
    const int address = word_at(pdu + 1);
    const int count = word_at(pdu + 3);
    reply_pdu = {pdu[0], static_cast<std::uint8_t>(2 * count)};
    for (int i = 0; i < count; ++i) {
      const std::uint16_t value = address + i < register_count ? registers[address + i] : 0;
      reply_pdu.push_back(static_cast<std::uint8_t>(value >> 8));
      reply_pdu.push_back(static_cast<std::uint8_t>(value & 0xFF));
    }
  } else {  // writes echo function, address and value/count
    for (int i = 0; i < 5; ++i) reply_pdu.push_back(pdu[i]);
  }
  std::vector<std::uint8_t> frame;
  if (rtu) {
    frame.push_back(query[0]);  // slave
    for (const std::uint8_t byte : reply_pdu) frame.push_back(byte);
    const std::uint16_t wrong = static_cast<std::uint16_t>(crc16_modbus(frame) ^ 0xFFFF);
    frame.push_back(static_cast<std::uint8_t>(wrong & 0xFF));  // CRC goes low byte first
    frame.push_back(static_cast<std::uint8_t>(wrong >> 8));
  } else {
    const int length = static_cast<int>(reply_pdu.size()) + 1;
    frame = {static_cast<std::uint8_t>(query[0] ^ 0x5A), query[1], 0, 0, static_cast<std::uint8_t>(length >> 8),
             static_cast<std::uint8_t>(length & 0xFF),   query[6]};
    for (const std::uint8_t byte : reply_pdu) frame.push_back(byte);
  }
  return frame;
}

}  // namespace glider::sim_tools
