// SPDX-License-Identifier: Apache-2.0
#pragma once
// One position-controlled actuator axis behind the default register map
// (register_map.hpp), in engineering units (cc or in). Used by the flight
// HAL (modbus_actuators.hpp) and by the bench tool. Nothing here throws or
// allocates; every call is bounded by the link's timeouts and budget.
#include <cstdint>

#include "glider/hal/actuator.hpp"
#include "glider/hal_linux/modbus_board.hpp"
#include "glider/hal_linux/modbus_link.hpp"

namespace glider::hal_linux {

struct AxisStatus {
  bool answered = false;  // false: nothing below is valid, see error
  double position = 0.0;  // unit
  double speed = 0.0;     // unit/s
  std::uint16_t status_bits = 0;
  std::uint16_t fault_code = 0;
  const char* error = "";  // why not answered (static string)

  bool has(std::uint16_t status_bit) const { return (status_bits & status_bit) != 0; }
};

struct AxisIdentity {
  bool answered = false;
  bool recognised = false;  // the ident register holds the map's value
  std::uint16_t ident = 0;
  std::uint16_t version = 0;
  const char* error = "";
};

class ModbusAxis {
 public:
  ModbusAxis(ModbusLink& link, const AxisConfig& config) : link_(link), config_(config) {}

  const AxisConfig& config() const { return config_; }
  bool within_limits(double target) const { return target >= config_.min && target <= config_.max; }

  // Enables the drive and sends the target at the configured rate (or
  // `rate`, clamped to max_rate). A target outside the command limits is not
  // sent and latches a fault until the next valid command. A command that
  // cannot be delivered now stays pending and is retried by read().
  bool command(double target) noexcept { return command(target, config_.rate); }
  bool command(double target, double rate) noexcept;
  bool home() noexcept;
  bool stop() noexcept;
  bool clear_fault() noexcept;

  AxisIdentity identify() noexcept;
  AxisStatus read_status() noexcept;

  // The flight loop's view: valid only with an answer; fault when the device
  // reports one, does not answer, holds an implausible position, or the last
  // command was refused or is still undelivered.
  hal::ActuatorReading read(hal::Micros now_us) noexcept;

  bool command_pending() const { return pending_; }
  bool command_refused() const { return refused_; }

 private:
  bool send_control(std::uint16_t control) noexcept;
  bool deliver_pending() noexcept;
  int address(int offset) const { return config_.base_address + offset; }

  ModbusLink& link_;
  AxisConfig config_;
  std::uint16_t pending_block_[3] = {0, 0, 0};  // control, target, speed
  bool pending_ = false;
  bool refused_ = false;
};

}  // namespace glider::hal_linux
