// SPDX-License-Identifier: Apache-2.0
#pragma once
// The set of hardware services the flight software is built against.
#include "glider/hal/attitude_sensor.hpp"
#include "glider/hal/battery_slide.hpp"
#include "glider/hal/buoyancy_pump.hpp"
#include "glider/hal/clock.hpp"
#include "glider/hal/depth_sensor.hpp"
#include "glider/hal/digital_io.hpp"
#include "glider/hal/gps.hpp"
#include "glider/hal/log_record.hpp"
#include "glider/hal/power_monitor.hpp"
#include "glider/hal/rudder.hpp"

namespace glider::hal {

struct Hal {
  Clock& clock;
  DepthSensor& depth;
  AttitudeSensor& attitude;
  BuoyancyPump& pump;
  BatterySlide& battery;
  LogSink& log;
  Rudder& rudder;
  GpsReceiver& gps;
  DigitalInput& leak;          // leak detector (active = water inside)
  DigitalOutput& drop_weight;  // burn wire of the emergency weight (active = release)
  PowerMonitor& power;
};

}  // namespace glider::hal
