// SPDX-License-Identifier: Apache-2.0
#pragma once
// The call's raw byte stream as the file-transfer engine sees it: read what
// has arrived, write what fits, never block. Identical in spirit to the
// Zmodem engine's ByteStream (branch zmodem, comms/byte_stream.hpp); the two
// are to be reconciled into one at the merge.
#include <cstddef>
#include <cstdint>
#include <span>

#include "glider/hal/modem.hpp"

namespace glider::fw::comms {

class DataStream {
 public:
  virtual ~DataStream() = default;
  virtual std::size_t read(std::span<std::uint8_t> buffer) = 0;
  virtual std::size_t write(std::span<const std::uint8_t> bytes) = 0;
};

// The modem in data mode (after CONNECT) as a DataStream.
class ModemStream final : public DataStream {
 public:
  explicit ModemStream(hal::Modem& modem) : modem_(modem) {}
  std::size_t read(std::span<std::uint8_t> buffer) override { return modem_.read(buffer); }
  std::size_t write(std::span<const std::uint8_t> bytes) override { return modem_.write(bytes); }

 private:
  hal::Modem& modem_;
};

}  // namespace glider::fw::comms
