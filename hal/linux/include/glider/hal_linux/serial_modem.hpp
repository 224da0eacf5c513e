// SPDX-License-Identifier: Apache-2.0
#pragma once
// The modem on a serial line (an Iridium 9523/9603-class data modem on a
// UART or USB serial port): raw, non-blocking, what arrived and what fits.
// Carrier detect from the DCD wire when the board says it is wired
// (`[modem] dcd = true`); otherwise kUnknown and the firmware goes by the
// modem's own "NO CARRIER".
#include <memory>
#include <string>

#include "glider/hal/modem.hpp"
#include "glider/hal_linux/serial_port.hpp"

namespace glider::hal_linux {

struct SerialModemConfig {
  std::string device;
  int baud = 19200;
  bool dcd_wired = false;
};

class SerialModem final : public hal::Modem {
 public:
  // Start-up: opens the line (throws std::runtime_error naming the device).
  explicit SerialModem(const SerialModemConfig& config);

  std::size_t read(std::span<std::uint8_t> buffer) override;
  std::size_t write(std::span<const std::uint8_t> bytes) override;
  hal::Carrier carrier() const override;
  const SerialPortStats& stats() const { return port_->stats(); }

 private:
  std::unique_ptr<SerialPort> port_;
  bool dcd_wired_;
};

}  // namespace glider::hal_linux
