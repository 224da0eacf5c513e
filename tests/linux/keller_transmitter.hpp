// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <modbus/modbus.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include "glider/hal_linux/keller_depth.hpp"

namespace glider::test {

// A Keller Series 30 class transmitter on a serial line (libmodbus RTU
// server, slave 1, 9600 8N1): P1 and TOB1 as Keller floats at their
// addresses, served from a thread until stop().
class KellerTransmitter {
 public:
  explicit KellerTransmitter(const std::string& device) : mapping_(modbus_mapping_new(0, 0, 0x20, 0)) {
    context_ = modbus_new_rtu(device.c_str(), 9600, 'N', 8, 1);
    modbus_set_slave(context_, 1);
    modbus_connect(context_);
    modbus_set_indication_timeout(context_, 0, 100'000);  // so that stop() is seen
    set(1.01325f, 12.5f);
    thread_ = std::thread([this] { serve(); });
  }
  ~KellerTransmitter() { stop(); }
  void set(float pressure_bar, float temperature_c) {
    std::lock_guard lock(mutex_);
    put(hal_linux::keller::kP1Address, pressure_bar);
    put(hal_linux::keller::kP1Address + hal_linux::keller::kTob1Offset, temperature_c);
  }
  void stop() {
    if (!running_.exchange(false)) return;
    thread_.join();
    modbus_close(context_);
    modbus_free(context_);
    modbus_mapping_free(mapping_);
  }

 private:
  void put(int address, float value) {
    const auto bits = std::bit_cast<std::uint32_t>(value);
    mapping_->tab_registers[address] = static_cast<std::uint16_t>(bits >> 16);  // high word first
    mapping_->tab_registers[address + 1] = static_cast<std::uint16_t>(bits & 0xffff);
  }
  void serve() {
    std::uint8_t query[MODBUS_RTU_MAX_ADU_LENGTH];
    while (running_) {
      const int length = modbus_receive(context_, query);
      if (length <= 0) continue;
      std::lock_guard lock(mutex_);
      modbus_reply(context_, query, length, mapping_);
    }
  }
  modbus_mapping_t* mapping_;
  modbus_t* context_;
  std::mutex mutex_;
  std::atomic<bool> running_{true};
  std::thread thread_;
};

}  // namespace glider::test
