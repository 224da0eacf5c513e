// SPDX-License-Identifier: Apache-2.0
#pragma once
// One simulated actuator axis behind the default register map: a
// rate-limited position servo with limit switches, homing and latched
// faults. Pure computation; the server moves registers in and out.
#include <cstdint>

#include "glider/hal_linux/modbus_board.hpp"

namespace glider::sim_tools {

class SimulatedAxis {
 public:
  // stall_after_s >= 0: the mechanism jams after moving that long (once).
  SimulatedAxis(const hal_linux::AxisConfig& config, double stall_after_s);

  // Advance the mechanism by dt seconds (simulated time).
  void step(double dt_s);
  // The registers [base, base + kBlockLength): commands in, state out.
  // take_commands() clears the self-clearing bits it acted on.
  void take_commands(std::uint16_t* block);
  void publish(std::uint16_t* block) const;

  double position() const { return position_; }

 private:
  double clamp_to_travel(double x) const;

  hal_linux::AxisConfig config_;
  double stall_after_s_;
  double position_ = 0.0;
  double target_ = 0.0;
  double rate_ = 0.0;
  double speed_ = 0.0;
  double moving_time_s_ = 0.0;
  bool enabled_ = false;
  bool stopped_ = false;
  bool homing_ = false;
  bool homed_ = false;
  std::uint16_t fault_ = 0;
};

}  // namespace glider::sim_tools
