// SPDX-License-Identifier: Apache-2.0
#pragma once
// Stand-ins for devices a vehicle does not have (not fitted: the board file on
// the target, the vehicle file in SIL), so that the flight software always
// gets a complete hal::Hal. Each says plainly what it is: a fixed fin
// (a glider without a rudder axis flies with its fin locked at zero, which
// is a valid, known position), and a leak detector, drop weight and power
// monitor that never have a reading (the firmware logs them as missing; the
// start-up output already warned that the board has none).
#include "glider/hal/clock.hpp"
#include "glider/hal/digital_io.hpp"
#include "glider/hal/power_monitor.hpp"
#include "glider/hal/rudder.hpp"

namespace glider::fw::app {

class FixedRudder final : public hal::Rudder {
 public:
  explicit FixedRudder(const hal::Clock& clock) : clock_(clock) {}
  void command_angle_rad(double) override {}
  hal::ActuatorReading read_angle_rad() override { return {0.0, clock_.now_us(), true, false}; }

 private:
  const hal::Clock& clock_;
};

class NoDigitalInput final : public hal::DigitalInput {
 public:
  hal::DigitalSample read() override { return {}; }
};

class NoDigitalOutput final : public hal::DigitalOutput {
 public:
  bool set(bool) override { return false; }
};

class NoPowerMonitor final : public hal::PowerMonitor {
 public:
  hal::PowerSample read() override { return {}; }
};

}  // namespace glider::fw::app
