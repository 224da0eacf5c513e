// SPDX-License-Identifier: Apache-2.0
#pragma once
// The flight HAL of the Linux target, built from a target board file: every
// device opened and checked at start-up (a missing one is an error naming
// its board file), owned here for the life of the firmware.
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "glider/firmware/app/absent_devices.hpp"
#include "glider/hal/hal.hpp"
#include "glider/hal_linux/gpio_lines.hpp"
#include "glider/hal_linux/hwmon_power.hpp"
#include "glider/hal_linux/keller_depth.hpp"
#include "glider/hal_linux/modbus_actuators.hpp"
#include "glider/hal_linux/modbus_link.hpp"
#include "glider/hal_linux/serial_sensors.hpp"
#include "glider/target/loop_clock.hpp"
#include "glider/target/ring_log.hpp"
#include "glider/target/target_board.hpp"

namespace glider::target {

struct LinuxHalOptions {
  std::string actuators_tcp;  // "HOST:PORT": override the actuator board's bus (bench, tests)
  std::string log_path;       // the flight log file
  double time_scale = 1.0;    // the loop clock's rate (bench/HIL only; loop_clock.hpp)
  std::vector<std::pair<std::string, std::string>> log_metadata;  // `# key: value` lines of the flight log
  fw::SlocumLogger* slocum = nullptr;  // the Slocum data files, fed by the log's writer thread (not owned)
};

class LinuxHal {
 public:
  // Throws config::ConfigError or std::runtime_error naming the device or
  // file that is missing or wrong. Non-fatal findings go to `log`.
  static std::unique_ptr<LinuxHal> build(const TargetBoard& board, const LinuxHalOptions& options, std::FILE* log);

  hal::Hal hal();
  // A new control cycle: fresh blocking budgets on the Modbus buses.
  void begin_cycle() noexcept;

  hal::GpsReceiver& gps() { return *gps_; }
  hal::DigitalInput* leak();                           // null without a GPIO board
  hal::DigitalOutput* drop_weight();                   // null without a GPIO board
  hal::Rudder* rudder() { return rudder_.get(); }      // null without [rudder] on the actuator board
  hal::PowerMonitor* power() { return power_.get(); }  // null without [power]
  RingBufferLog& log() { return *log_; }
  const LoopClock& clock() const { return clock_; }

  // Every driver's counters, one line each, for the log at the end.
  void print_statistics(std::FILE* out) const;

 private:
  LinuxHal() = default;

  LoopClock clock_;
  // Stand-ins for what the board does not have (absent_devices.hpp).
  fw::app::FixedRudder fixed_rudder_{clock_};
  fw::app::NoDigitalInput no_leak_;
  fw::app::NoDigitalOutput no_drop_weight_;
  fw::app::NoPowerMonitor no_power_;
  hal_linux::ModbusBoard actuator_board_;
  std::unique_ptr<hal_linux::ModbusLink> actuator_link_;
  std::unique_ptr<hal_linux::ModbusAxis> pump_axis_;
  std::unique_ptr<hal_linux::ModbusAxis> slide_axis_;
  std::unique_ptr<hal_linux::ModbusBuoyancyPump> pump_;
  std::unique_ptr<hal_linux::ModbusBatterySlide> slide_;
  std::unique_ptr<hal_linux::ModbusAxis> rudder_axis_;
  std::unique_ptr<hal_linux::ModbusRudder> rudder_;
  std::unique_ptr<hal_linux::HwmonPowerMonitor> power_;
  std::unique_ptr<hal_linux::ModbusLink> depth_link_;
  std::unique_ptr<hal_linux::KellerDepthSensor> depth_;
  std::unique_ptr<hal_linux::NmeaGpsReceiver> gps_;
  std::unique_ptr<hal_linux::SerialCompass> compass_;
  std::unique_ptr<hal_linux::GpioLines> gpio_;
  std::unique_ptr<RingBufferLog> log_;
};

}  // namespace glider::target
