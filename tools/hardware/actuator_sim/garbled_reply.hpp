// SPDX-License-Identifier: Apache-2.0
#pragma once
// A reply that is wrong on purpose (line noise): the right length and
// header, so the client reads all of it, but a bad RTU CRC or, on TCP, a
// transaction id that does not match. libmodbus does not export its CRC, so
// the few lines of CRC-16/MODBUS live here, used only to get it wrong.
#include <cstdint>
#include <vector>

namespace glider::sim_tools {

// `query` as libmodbus received it (header_length bytes of header, then the
// PDU); `registers` the slave's holding registers.
std::vector<std::uint8_t> garbled_reply(const std::uint8_t* query, int header_length, bool rtu,
                                        const std::uint16_t* registers, int register_count);

}  // namespace glider::sim_tools
