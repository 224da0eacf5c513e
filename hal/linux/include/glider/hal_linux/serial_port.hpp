// SPDX-License-Identifier: Apache-2.0
#pragma once
// A serial line opened raw and non-blocking (termios, O_NONBLOCK): the
// sensors' drivers take what has arrived and never wait for more.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace glider::hal_linux {

struct SerialPortStats {
  std::uint64_t bytes = 0;
  std::uint64_t errors = 0;  // read errors other than "nothing there"
};

class SerialPort {
 public:
  // Start-up: opens `device` at `baud` 8N1, raw. Throws std::runtime_error
  // naming the device and the reason.
  static std::unique_ptr<SerialPort> open(const std::string& device, int baud);
  ~SerialPort();
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  // The bytes waiting, up to `size`: 0 when none (never blocks), -1 on error.
  long read_some(char* buffer, std::size_t size) noexcept;
  // What the driver's buffer takes of `size` bytes: 0 when full (never blocks), -1 on error.
  long write_some(const char* bytes, std::size_t size) noexcept;
  // Data carrier detect: 1 on, 0 off, -1 when the line cannot say (a pty, no modem-control wires).
  int carrier_detect() const noexcept;
  const SerialPortStats& stats() const { return stats_; }
  const std::string& device() const { return device_; }

 private:
  SerialPort(int fd, std::string device) : fd_(fd), device_(std::move(device)) {}
  int fd_;
  std::string device_;
  SerialPortStats stats_;
};

// True for the baud rates termios knows (300 .. 4000000).
bool supported_baud(int baud);

}  // namespace glider::hal_linux
