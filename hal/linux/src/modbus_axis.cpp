// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/modbus_axis.hpp"

#include <algorithm>
#include <cmath>

#include "glider/hal_linux/register_map.hpp"
#include "glider/units.hpp"

namespace glider::hal_linux {

bool ModbusAxis::command(double target, double rate) noexcept {
  const std::optional<std::int16_t> counts = value_to_counts(target, config_.counts_per_unit);
  if (!within_limits(target) || !counts || !(rate > 0.0)) {
    refused_ = true;
    return false;
  }
  const double counts_per_s = std::round(std::min(rate, config_.max_rate) * config_.counts_per_unit);
  refused_ = false;
  pending_block_[0] = regs::kEnable;
  pending_block_[1] = static_cast<std::uint16_t>(*counts);  // two's complement on the wire
  pending_block_[2] = static_cast<std::uint16_t>(std::max(1.0, counts_per_s));
  pending_ = true;
  return deliver_pending();
}

bool ModbusAxis::deliver_pending() noexcept {
  if (!pending_) return true;
  if (!link_.write_registers(config_.slave, address(regs::kCommandBlockStart), regs::kCommandBlockLength,
                             pending_block_)) {
    return false;
  }
  pending_ = false;
  return true;
}

bool ModbusAxis::send_control(std::uint16_t control) noexcept {
  return link_.write_registers(config_.slave, address(regs::kControl), 1, &control);
}

bool ModbusAxis::home() noexcept { return send_control(regs::kEnable | regs::kHome); }
bool ModbusAxis::stop() noexcept { return send_control(regs::kEnable | regs::kStop); }
bool ModbusAxis::clear_fault() noexcept { return send_control(regs::kClearFault); }

AxisIdentity ModbusAxis::identify() noexcept {
  AxisIdentity id;
  std::uint16_t words[2] = {0, 0};
  id.answered = link_.read_registers(config_.slave, address(regs::kIdent), 2, words);
  if (!id.answered) {
    id.error = link_.last_error();
    return id;
  }
  id.ident = words[0];
  id.version = words[1];
  id.recognised = words[0] == regs::kIdentValue && (words[1] >> 8) == (regs::kMapVersion >> 8);
  return id;
}

AxisStatus ModbusAxis::read_status() noexcept {
  AxisStatus s;
  std::uint16_t words[regs::kReadBlockLength] = {};
  s.answered = link_.read_registers(config_.slave, address(regs::kReadBlockStart), regs::kReadBlockLength, words);
  if (!s.answered) {
    s.error = link_.last_error();
    return s;
  }
  const auto word = [&](int offset) { return words[offset - regs::kReadBlockStart]; };
  s.position = counts_to_value(static_cast<std::int16_t>(word(regs::kActual)), config_.counts_per_unit);
  s.status_bits = word(regs::kStatus);
  s.fault_code = word(regs::kFaultCode);
  s.speed = counts_to_value(static_cast<std::int16_t>(word(regs::kActualSpeed)), config_.counts_per_unit);
  return s;
}

hal::ActuatorReading ModbusAxis::read(hal::Micros now_us) noexcept {
  deliver_pending();  // a command that did not get through earlier
  const AxisStatus s = read_status();
  hal::ActuatorReading reading;
  reading.time_us = now_us;
  if (!s.answered) {
    reading.fault = true;
    return reading;
  }
  // A position outside the mechanical travel (beyond one count) cannot be
  // true: a misconfigured map or scaling, not a value to fly on.
  const double tolerance = 1.0 / config_.counts_per_unit;
  const bool plausible = s.position >= config_.travel_min - tolerance && s.position <= config_.travel_max + tolerance;
  reading.position = s.position;
  reading.valid = plausible;
  reading.fault = !plausible || s.has(regs::kFault) || refused_ || pending_;
  return reading;
}

}  // namespace glider::hal_linux
