// SPDX-License-Identifier: Apache-2.0
#pragma once
// The simulator's checks on a Modbus TCP request before libmodbus answers it:
// where a frame ends in the client's byte stream, and whether the request is
// one the server serves (function, quantity, byte count). Pure functions of
// the bytes: the fuzz target tests/fuzz/fuzz_actuator_requests.cpp runs them.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace glider::sim_tools {

constexpr std::size_t kMbapHeaderLength = 7;     // transaction, protocol, length, unit id
constexpr std::size_t kMaxTcpFrameLength = 260;  // MODBUS_TCP_MAX_ADU_LENGTH
constexpr std::size_t kFrameIncomplete = 0;
constexpr std::size_t kFrameMalformed = static_cast<std::size_t>(-1);

// Size of the frame at the start of `bytes`: kFrameIncomplete until the whole
// frame is there, kFrameMalformed when the header cannot start a Modbus TCP
// frame (protocol id not 0, length field outside 2..254): the stream cannot
// be resynchronised, the client is dropped.
std::size_t tcp_frame_size(const std::uint8_t* bytes, std::size_t available);

// 0 when libmodbus may answer the frame, else the Modbus exception code to
// reply with (1 illegal function, 3 illegal data value): reads of 1..125
// registers (functions 3, 4), writes of one (6) or 1..123 (16) registers with
// a matching byte count. Other functions are not in the register map.
int request_exception(const std::uint8_t* frame, std::size_t length);

// The exception reply to a frame: its MBAP header, function | 0x80, code.
std::vector<std::uint8_t> exception_reply(const std::uint8_t* frame, int code);

}  // namespace glider::sim_tools
