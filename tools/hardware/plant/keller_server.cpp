// SPDX-License-Identifier: Apache-2.0
#include "keller_server.hpp"

#include <bit>
#include <cerrno>
#include <cstdint>
#include <stdexcept>

#include "glider/hal_linux/keller_depth.hpp"

namespace glider::plant {

namespace keller = hal_linux::keller;

KellerServer::KellerServer(int fd, const std::string& device_name, int slave) {
  // The device name is only a label: the line is the pty master we own.
  context_ = modbus_new_rtu(device_name.c_str(), 9600, 'N', 8, 1);
  if (context_ == nullptr) throw std::runtime_error(device_name + ": " + modbus_strerror(errno));
  modbus_set_slave(context_, slave);
  modbus_set_socket(context_, fd);
  // A request comes in one write: a gap longer than this ends a garbled one.
  modbus_set_byte_timeout(context_, 0, 50'000);
  modbus_set_indication_timeout(context_, 0, 50'000);
  modbus_set_response_timeout(context_, 0, 1'000);  // its sleep before a flush stalls the whole plant
  mapping_ = modbus_mapping_new(0, 0, keller::kP1Address + keller::kReadCount, 0);
  if (mapping_ == nullptr) throw std::runtime_error(device_name + ": modbus_mapping_new failed");
}

KellerServer::~KellerServer() {
  modbus_mapping_free(mapping_);
  modbus_set_socket(context_, -1);  // the fd is the caller's
  modbus_free(context_);
}

void KellerServer::put_float(int address, double value) {
  const auto bits = std::bit_cast<std::uint32_t>(static_cast<float>(value));
  mapping_->tab_registers[address] = static_cast<std::uint16_t>(bits >> 16);  // high word first (Keller)
  mapping_->tab_registers[address + 1] = static_cast<std::uint16_t>(bits & 0xffff);
}

void KellerServer::on_readable(const std::function<KellerReading()>& measure, bool silent) {
  std::uint8_t request[MODBUS_RTU_MAX_ADU_LENGTH];
  const int length = modbus_receive(context_, request);
  if (length <= 0) {
    if (length < 0) ++rejected_;
    return;
  }
  ++requests_;
  if (silent) return;
  const KellerReading reading = measure();
  put_float(keller::kP1Address, reading.pressure_bar);
  put_float(keller::kP1Address + keller::kTob1Offset, reading.temperature_c);
  modbus_reply(context_, request, length, mapping_);
}

}  // namespace glider::plant
