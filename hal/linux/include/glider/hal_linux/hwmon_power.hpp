// SPDX-License-Identifier: Apache-2.0
#pragma once
// The main battery through a Linux hwmon power monitor (INA219/INA226 class:
// the kernel's ina2xx driver, /sys/class/hwmon/hwmonN with name "ina219"):
// bus voltage from in1_input (mV), current from curr1_input (mA, + out of
// the battery), charge used integrated from the current between reads.
// The device is found by its hwmon `name` at start-up; the loop reads two
// already-open sysfs files with pread (no allocation, no exception).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "glider/hal/clock.hpp"
#include "glider/hal/power_monitor.hpp"

namespace glider::hal_linux {

struct PowerMonitorConfig {
  std::string hwmon_name = "ina219";
  std::filesystem::path hwmon_root = "/sys/class/hwmon";  // a test points it at a directory of files
  double charge_used_at_start_amphr = 0.0;                // from the last run (the operator or a state file)
  double min_voltage_v = 5.0;                             // outside [min, max]: not a battery reading
  double max_voltage_v = 30.0;
};

struct PowerMonitorStats {
  std::uint64_t reads = 0;
  std::uint64_t errors = 0;        // a file could not be read or parsed
  std::uint64_t out_of_range = 0;  // a voltage no battery of this board has
};

class HwmonPowerMonitor final : public hal::PowerMonitor {
 public:
  // Throws std::runtime_error naming the root and the name when no hwmon
  // device has that name or its files cannot be opened.
  static std::unique_ptr<HwmonPowerMonitor> open(const PowerMonitorConfig& config, const hal::Clock& clock);
  ~HwmonPowerMonitor() override;
  hal::PowerSample read() override;
  const PowerMonitorStats& stats() const { return stats_; }
  const std::filesystem::path& device() const { return device_; }

 private:
  HwmonPowerMonitor(const PowerMonitorConfig& config, const hal::Clock& clock, std::filesystem::path device,
                    int voltage_fd, int current_fd);
  PowerMonitorConfig config_;
  const hal::Clock& clock_;
  std::filesystem::path device_;
  int voltage_fd_;
  int current_fd_;
  double charge_used_amphr_;
  hal::Micros last_time_us_ = 0;
  double last_current_a_ = 0.0;
  bool have_last_ = false;
  PowerMonitorStats stats_;
};

}  // namespace glider::hal_linux
