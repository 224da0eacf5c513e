// SPDX-License-Identifier: Apache-2.0
#pragma once
// One actuator axis of the plant: the actuator simulator's axis (servo,
// limit switches, homing, latched faults: tools/hardware/actuator_sim/simulated_axis)
// behind its register block, plus what the plant can do to it from outside:
// start it where the pilot left it, and jam the mechanism at a given time.
// A jammed mechanism no longer moves; its controller notices when it is
// told to move and latches a Stall fault, as the real drive's stall
// detection does (clearing the fault only helps until the next move).
#include <cstdint>

#include "glider/hal_linux/modbus_board.hpp"
#include "simulated_axis.hpp"

namespace glider::plant {

class PlantAxis {
 public:
  // The mechanism starts at `start_position` (clamped to the travel),
  // disabled, as left before launch.
  PlantAxis(const hal_linux::AxisConfig& config, double start_position);

  // After a register write: the commands in the block take effect.
  void take_commands(std::uint16_t* block);
  // Advance the mechanism by dt (simulated seconds), then publish its state.
  void step(double dt_s, std::uint16_t* block);
  void publish(std::uint16_t* block) const;
  // The command registers as left before launch (drive off, target where
  // the mechanism is), so that a write to another axis changes nothing here.
  void initial_commands(std::uint16_t* block) const;
  void jam() { jammed_ = true; }

  double position() const { return axis_.position(); }
  const hal_linux::AxisConfig& config() const { return config_; }
  int slave() const { return config_.slave; }
  int base() const { return config_.base_address; }

 private:
  bool told_to_move(const std::uint16_t* block) const;

  hal_linux::AxisConfig config_;
  sim_tools::SimulatedAxis axis_;
  bool jammed_ = false;
  bool stall_latched_ = false;
};

}  // namespace glider::plant
