// SPDX-License-Identifier: Apache-2.0
#pragma once
// A scripted HAL for firmware tests: tests set what the sensors say and read
// back what the firmware commanded and logged.
#include <limits>

#include "glider/hal/hal.hpp"

namespace glider::test {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A scripted HAL: tests set what the sensors say and read what was commanded.
struct FakeHal final : hal::Clock, hal::DepthSensor, hal::BuoyancyPump, hal::BatterySlide, hal::LogSink {
  struct Attitude final : hal::AttitudeSensor {
    hal::AttitudeSample sample{};
    hal::AttitudeSample read() override { return sample; }
  } attitude;

  struct Rudder final : hal::Rudder {
    double commanded_rad = 0.0;
    bool fault = false;
    const hal::Micros* now = nullptr;
    void command_angle_rad(double a) override { commanded_rad = a; }
    hal::ActuatorReading read_angle_rad() override { return {commanded_rad, *now, true, fault}; }
  } rudder;
  struct Gps final : hal::GpsReceiver {
    hal::GpsFix fix{};
    hal::GpsFix read() override { return fix; }
  } gps;
  struct Leak final : hal::DigitalInput {
    hal::DigitalSample sample{false, 0, true};
    hal::DigitalSample read() override { return sample; }
  } leak;
  struct DropWeight final : hal::DigitalOutput {
    bool released = false;
    bool set(bool active) override {
      released = released || active;
      return true;
    }
  } drop_weight;
  struct Power final : hal::PowerMonitor {
    hal::PowerSample sample{15.0, 0.0, 0, true};
    hal::PowerSample read() override { return sample; }
  } power;

  FakeHal() { rudder.now = &now; }
  FakeHal(const FakeHal&) = delete;
  FakeHal& operator=(const FakeHal&) = delete;

  hal::Micros now = 0;
  hal::DepthSample depth{};
  double pump_cc = 250.0;
  double battery_in = 0.0;
  bool pump_fault = false;
  double commanded_cc = kNaN;
  double commanded_in = kNaN;
  int pump_commands = 0;
  bool accept_log = true;
  hal::FlightLogRecord last_row{};
  int rows = 0;

  hal::Micros now_us() const override { return now; }
  hal::DepthSample read() override { return depth; }
  void command_volume_cc(double cc) override {
    commanded_cc = cc;
    ++pump_commands;
  }
  hal::ActuatorReading read_volume_cc() override { return {pump_cc, now, true, pump_fault}; }
  void command_position_in(double in) override { commanded_in = in; }
  hal::ActuatorReading read_position_in() override { return {battery_in, now, true, false}; }
  bool write(const hal::FlightLogRecord& row) override {
    last_row = row;
    ++rows;
    return accept_log;
  }

  void sense(double depth_m, double pitch_rad) {
    depth = {depth_m, now, true};
    attitude.sample = {pitch_rad, 0.0, 1.0, now, true};
    leak.sample.time_us = now;
    power.sample.time_us = now;
  }
  hal::Hal hal() { return with_actuators(*this, *this); }
  // The fake's sensors with other pump and slide drivers (e.g. Modbus).
  hal::Hal with_actuators(hal::BuoyancyPump& pump, hal::BatterySlide& slide) {
    return {.clock = *this,
            .depth = *this,
            .attitude = attitude,
            .pump = pump,
            .battery = slide,
            .log = *this,
            .rudder = rudder,
            .gps = gps,
            .leak = leak,
            .drop_weight = drop_weight,
            .power = power};
  }
};

}  // namespace glider::test
