// SPDX-License-Identifier: Apache-2.0
#include "simulated_axis.hpp"

#include <algorithm>
#include <cmath>

#include "glider/hal_linux/register_map.hpp"
#include "glider/units.hpp"

namespace glider::sim_tools {

namespace regs = hal_linux::regs;

SimulatedAxis::SimulatedAxis(const hal_linux::AxisConfig& config, double stall_after_s)
    : config_(config), stall_after_s_(stall_after_s), position_(std::clamp(0.0, config.travel_min, config.travel_max)) {
  target_ = position_;
}

double SimulatedAxis::clamp_to_travel(double x) const { return std::clamp(x, config_.travel_min, config_.travel_max); }

void SimulatedAxis::step(double dt_s) {
  speed_ = 0.0;
  if (dt_s <= 0.0 || fault_ != regs::kNoFault || !enabled_ || (stopped_ && !homing_)) return;
  const double goal = homing_ ? config_.travel_min : clamp_to_travel(target_);
  const double rate = homing_ ? config_.max_rate : std::min(rate_, config_.max_rate);
  const double step = std::clamp(goal - position_, -rate * dt_s, rate * dt_s);
  if (step == 0.0) return;
  if (stall_after_s_ >= 0.0 && moving_time_s_ + dt_s >= stall_after_s_) {
    fault_ = regs::kStall;  // jammed: no more motion until the fault is cleared
    stall_after_s_ = -1.0;
    return;
  }
  moving_time_s_ += dt_s;
  position_ += step;
  speed_ = step / dt_s;
  const bool arrived = position_ == goal;
  if (homing_ && arrived) {
    homing_ = false;
    homed_ = true;
    target_ = position_;
  } else if (arrived && goal != target_) {
    fault_ = regs::kOverTravel;  // the target lies beyond a limit switch
  }
}

void SimulatedAxis::take_commands(std::uint16_t* block) {
  const std::uint16_t control = block[regs::kControl];
  if ((control & regs::kClearFault) != 0) fault_ = regs::kNoFault;
  enabled_ = (control & regs::kEnable) != 0;
  stopped_ = (control & regs::kStop) != 0;
  if ((control & regs::kHome) != 0 && enabled_) homing_ = true;
  block[regs::kControl] = static_cast<std::uint16_t>(control & ~(regs::kHome | regs::kClearFault));
  if (!homing_) target_ = counts_to_value(static_cast<std::int16_t>(block[regs::kTarget]), config_.counts_per_unit);
  rate_ = static_cast<double>(block[regs::kSpeed]) / config_.counts_per_unit;
}

void SimulatedAxis::publish(std::uint16_t* block) const {
  const double count = 1.0 / config_.counts_per_unit;
  const bool moving = speed_ != 0.0;
  std::uint16_t status = 0;
  if (enabled_) status |= regs::kEnabled;
  if (moving) status |= regs::kMoving;
  if (!moving && std::abs(position_ - target_) < count) status |= regs::kInPosition;
  if (homed_) status |= regs::kHomed;
  if (position_ <= config_.travel_min + count / 2) status |= regs::kLimitMin;
  if (position_ >= config_.travel_max - count / 2) status |= regs::kLimitMax;
  if (fault_ != regs::kNoFault) status |= regs::kFault;
  block[regs::kIdent] = regs::kIdentValue;
  block[regs::kVersion] = regs::kMapVersion;
  block[regs::kActual] = static_cast<std::uint16_t>(value_to_counts(position_, config_.counts_per_unit).value_or(0));
  block[regs::kStatus] = status;
  block[regs::kFaultCode] = fault_;
  block[regs::kActualSpeed] = static_cast<std::uint16_t>(value_to_counts(speed_, config_.counts_per_unit).value_or(0));
}

}  // namespace glider::sim_tools
