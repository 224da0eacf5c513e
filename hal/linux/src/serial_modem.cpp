// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/serial_modem.hpp"

namespace glider::hal_linux {

SerialModem::SerialModem(const SerialModemConfig& config)
    : port_(SerialPort::open(config.device, config.baud)), dcd_wired_(config.dcd_wired) {}

std::size_t SerialModem::read(std::span<std::uint8_t> buffer) {
  const long n = port_->read_some(reinterpret_cast<char*>(buffer.data()), buffer.size());
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

std::size_t SerialModem::write(std::span<const std::uint8_t> bytes) {
  const long n = port_->write_some(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

hal::Carrier SerialModem::carrier() const {
  if (!dcd_wired_) return hal::Carrier::kUnknown;
  const int dcd = port_->carrier_detect();
  return dcd < 0 ? hal::Carrier::kUnknown : dcd == 1 ? hal::Carrier::kPresent : hal::Carrier::kLost;
}

}  // namespace glider::hal_linux
