#pragma once
// The set of hardware services the flight software is built against.
#include "glider/hal/attitude_sensor.hpp"
#include "glider/hal/battery_slide.hpp"
#include "glider/hal/buoyancy_pump.hpp"
#include "glider/hal/clock.hpp"
#include "glider/hal/depth_sensor.hpp"
#include "glider/hal/log_record.hpp"

namespace glider::hal {

struct Hal {
  Clock& clock;
  DepthSensor& depth;
  AttitudeSensor& attitude;
  BuoyancyPump& pump;
  BatterySlide& battery;
  LogSink& log;
};

}  // namespace glider::hal
