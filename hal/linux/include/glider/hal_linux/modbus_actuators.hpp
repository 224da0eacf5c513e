// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight HAL's buoyancy pump and battery slide on Modbus axes. Thin:
// the axis does the work; these only tie it to the HAL interfaces and clock.
#include "glider/hal/battery_slide.hpp"
#include "glider/hal/buoyancy_pump.hpp"
#include "glider/hal/clock.hpp"
#include "glider/hal/rudder.hpp"
#include "glider/hal_linux/modbus_axis.hpp"
#include "glider/units.hpp"

namespace glider::hal_linux {

class ModbusBuoyancyPump final : public hal::BuoyancyPump {
 public:
  ModbusBuoyancyPump(ModbusAxis& axis, const hal::Clock& clock) : axis_(axis), clock_(clock) {}
  void command_volume_cc(double volume_cc) override { axis_.command(volume_cc); }
  hal::ActuatorReading read_volume_cc() override { return axis_.read(clock_.now_us()); }

 private:
  ModbusAxis& axis_;
  const hal::Clock& clock_;
};

class ModbusBatterySlide final : public hal::BatterySlide {
 public:
  ModbusBatterySlide(ModbusAxis& axis, const hal::Clock& clock) : axis_(axis), clock_(clock) {}
  void command_position_in(double position_in) override { axis_.command(position_in); }
  hal::ActuatorReading read_position_in() override { return axis_.read(clock_.now_us()); }

 private:
  ModbusAxis& axis_;
  const hal::Clock& clock_;
};

// The fin on a Modbus axis in degrees (the register map's unit); the HAL's
// radians are converted here.
class ModbusRudder final : public hal::Rudder {
 public:
  ModbusRudder(ModbusAxis& axis, const hal::Clock& clock) : axis_(axis), clock_(clock) {}
  void command_angle_rad(double angle_rad) override { axis_.command(rad_to_deg(angle_rad)); }
  hal::ActuatorReading read_angle_rad() override {
    hal::ActuatorReading reading = axis_.read(clock_.now_us());
    reading.position = deg_to_rad(reading.position);
    return reading;
  }

 private:
  ModbusAxis& axis_;
  const hal::Clock& clock_;
};

// CLOCK_MONOTONIC as the HAL clock.
class MonotonicClock final : public hal::Clock {
 public:
  hal::Micros now_us() const override;
};

}  // namespace glider::hal_linux
