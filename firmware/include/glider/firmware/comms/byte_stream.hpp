// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>

namespace glider::fw::comms {

// A non-blocking byte pipe (a serial port, a modem's data mode, a socket, an
// in-memory link in tests). Both calls return at once: read() gives what has
// arrived (0 if nothing), write() takes what fits (0 if the link is full).
// Neither ever blocks the control loop.
class ByteStream {
 public:
  virtual ~ByteStream() = default;
  virtual std::size_t read(std::span<std::uint8_t> out) = 0;
  virtual std::size_t write(std::span<const std::uint8_t> data) = 0;
};

}  // namespace glider::fw::comms
