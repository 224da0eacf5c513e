// SPDX-License-Identifier: Apache-2.0
#pragma once
// The modem (an Iridium-class data modem, RUDICS): a serial byte stream the
// firmware speaks Hayes AT commands over, and then the call's raw bytes.
// Non-blocking both ways: read() takes what has arrived, write() what fits.
#include <cstddef>
#include <cstdint>
#include <span>

namespace glider::hal {

enum class Carrier : std::int32_t {
  kUnknown = 0,  // the line has no carrier-detect wire (the AT dialog decides)
  kLost = 1,
  kPresent = 2,
};

class Modem {
 public:
  virtual ~Modem() = default;
  // Up to buffer.size() bytes that have arrived; 0 when none. Never blocks.
  virtual std::size_t read(std::span<std::uint8_t> buffer) = 0;
  // Queues what fits of `bytes`; returns how many were taken. Never blocks.
  virtual std::size_t write(std::span<const std::uint8_t> bytes) = 0;
  // DCD where the serial line has it.
  virtual Carrier carrier() const = 0;
};

}  // namespace glider::hal
