// SPDX-License-Identifier: Apache-2.0
#pragma once
// The modem in data mode (after CONNECT) as the call's ByteStream: what the
// console and the Zmodem engine read from and write to. One stream
// interface for both (the comms branch's DataStream was merged into it).
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/firmware/comms/byte_stream.hpp"
#include "glider/hal/modem.hpp"

namespace glider::fw::comms {

class ModemStream final : public ByteStream {
 public:
  explicit ModemStream(hal::Modem& modem) : modem_(modem) {}
  std::size_t read(std::span<std::uint8_t> buffer) override { return modem_.read(buffer); }
  std::size_t write(std::span<const std::uint8_t> bytes) override { return modem_.write(bytes); }

 private:
  hal::Modem& modem_;
};

}  // namespace glider::fw::comms
