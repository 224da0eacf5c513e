// SPDX-License-Identifier: Apache-2.0
#include "plant_axis.hpp"

#include <algorithm>
#include <cmath>

#include "glider/hal_linux/register_map.hpp"
#include "glider/units.hpp"

namespace glider::plant {

namespace regs = hal_linux::regs;

PlantAxis::PlantAxis(const hal_linux::AxisConfig& config, double start_position)
    : config_(config), axis_(config, -1.0) {
  // Drive the simulated mechanism to the start through its own register
  // interface (enable, target, fastest speed), then switch it off: the
  // axis' behaviour stays the actuator simulator's, untouched.
  const double start = std::clamp(start_position, config.travel_min, config.travel_max);
  std::uint16_t block[regs::kBlockLength] = {};
  block[regs::kControl] = regs::kEnable;
  block[regs::kTarget] = static_cast<std::uint16_t>(value_to_counts(start, config.counts_per_unit).value_or(0));
  block[regs::kSpeed] = static_cast<std::uint16_t>(std::lround(config.max_rate * config.counts_per_unit));
  axis_.take_commands(block);
  const double travel_s = (config.travel_max - config.travel_min) / config.max_rate;
  for (int i = 0; i < static_cast<int>(travel_s / 0.1) + 20; ++i) axis_.step(0.1);
  block[regs::kControl] = 0;
  axis_.take_commands(block);
  axis_.step(0.0);
}

bool PlantAxis::told_to_move(const std::uint16_t* block) const {
  const std::uint16_t control = block[regs::kControl];
  if ((control & regs::kEnable) == 0 || (control & regs::kStop) != 0) return false;
  if ((control & regs::kHome) != 0) return true;
  const double target = counts_to_value(static_cast<std::int16_t>(block[regs::kTarget]), config_.counts_per_unit);
  return std::abs(std::clamp(target, config_.travel_min, config_.travel_max) - axis_.position()) >=
         1.0 / config_.counts_per_unit;
}

void PlantAxis::take_commands(std::uint16_t* block) {
  if ((block[regs::kControl] & regs::kClearFault) != 0) stall_latched_ = false;
  axis_.take_commands(block);
  publish(block);
}

void PlantAxis::step(double dt_s, std::uint16_t* block) {
  if (jammed_) {
    axis_.step(0.0);  // no motion (and no measured speed)
    if (told_to_move(block)) stall_latched_ = true;
  } else {
    axis_.step(dt_s);
  }
  publish(block);
}

void PlantAxis::initial_commands(std::uint16_t* block) const {
  block[regs::kControl] = 0;
  block[regs::kTarget] =
      static_cast<std::uint16_t>(value_to_counts(axis_.position(), config_.counts_per_unit).value_or(0));
  block[regs::kSpeed] = 0;
  publish(block);
}

void PlantAxis::publish(std::uint16_t* block) const {
  axis_.publish(block);
  if (stall_latched_) {
    block[regs::kStatus] = static_cast<std::uint16_t>((block[regs::kStatus] | regs::kFault) & ~regs::kInPosition);
    block[regs::kFaultCode] = regs::kStall;
  }
}

}  // namespace glider::plant
