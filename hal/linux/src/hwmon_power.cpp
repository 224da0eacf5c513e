// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/hwmon_power.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <charconv>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace glider::hal_linux {
namespace {

// One integer of a sysfs attribute ("12345\n"), read from offset 0.
std::optional<long> read_integer(int fd) {
  char text[32];
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return std::nullopt;
  std::size_t length = static_cast<std::size_t>(n);
  while (length > 0 && (text[length - 1] == '\n' || text[length - 1] == ' ')) --length;
  long value = 0;
  const auto [end, ec] = std::from_chars(text, text + length, value);
  if (ec != std::errc() || end != text + length || length == 0) return std::nullopt;
  return value;
}

std::filesystem::path find_device(const PowerMonitorConfig& config) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(config.hwmon_root, ec)) {
    std::ifstream name_file(entry.path() / "name");
    std::string name;
    if (name_file >> name && name == config.hwmon_name) return entry.path();
  }
  throw std::runtime_error("power monitor: no hwmon device named \"" + config.hwmon_name + "\" in " +
                           config.hwmon_root.string() + " (is the ina2xx driver bound? see dmesg)");
}

int open_attribute(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("power monitor: cannot open " + path.string());
  return fd;
}

}  // namespace

std::unique_ptr<HwmonPowerMonitor> HwmonPowerMonitor::open(const PowerMonitorConfig& config, const hal::Clock& clock) {
  const std::filesystem::path device = find_device(config);
  const int voltage_fd = open_attribute(device / "in1_input");
  int current_fd = -1;
  try {
    current_fd = open_attribute(device / "curr1_input");
  } catch (...) {
    ::close(voltage_fd);
    throw;
  }
  return std::unique_ptr<HwmonPowerMonitor>(new HwmonPowerMonitor(config, clock, device, voltage_fd, current_fd));
}

HwmonPowerMonitor::HwmonPowerMonitor(const PowerMonitorConfig& config, const hal::Clock& clock,
                                     std::filesystem::path device, int voltage_fd, int current_fd)
    : config_(config),
      clock_(clock),
      device_(std::move(device)),
      voltage_fd_(voltage_fd),
      current_fd_(current_fd),
      charge_used_amphr_(config.charge_used_at_start_amphr) {}

HwmonPowerMonitor::~HwmonPowerMonitor() {
  ::close(voltage_fd_);
  ::close(current_fd_);
}

hal::PowerSample HwmonPowerMonitor::read() {
  hal::PowerSample sample;
  ++stats_.reads;
  sample.time_us = clock_.now_us();
  const auto millivolts = read_integer(voltage_fd_);
  const auto milliamps = read_integer(current_fd_);
  if (!millivolts || !milliamps) {
    ++stats_.errors;
    return sample;
  }
  const double voltage = static_cast<double>(*millivolts) * 1e-3;
  const double current = static_cast<double>(*milliamps) * 1e-3;
  if (voltage < config_.min_voltage_v || voltage > config_.max_voltage_v) {
    ++stats_.out_of_range;
    return sample;
  }
  // Trapezoidal integration of the current between two good reads.
  if (have_last_) {
    const double hours = hal::to_seconds(sample.time_us - last_time_us_) / 3600.0;
    charge_used_amphr_ += 0.5 * (current + last_current_a_) * hours;
  }
  last_time_us_ = sample.time_us;
  last_current_a_ = current;
  have_last_ = true;
  sample.battery_voltage_v = voltage;
  sample.charge_used_amphr = charge_used_amphr_;
  sample.valid = true;
  return sample;
}

}  // namespace glider::hal_linux
