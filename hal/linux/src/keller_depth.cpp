// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/keller_depth.hpp"

#include <bit>
#include <cmath>

#include "glider/units.hpp"

namespace glider::hal_linux {
namespace {

constexpr double kStandardGravity = 9.80665;  // m/s^2
// A TOB1 outside this is a broken sensor, not water.
constexpr double kMinTemperatureC = -5.0;
constexpr double kMaxTemperatureC = 50.0;

}  // namespace

float keller_float(std::uint16_t high_word, std::uint16_t low_word) {
  return std::bit_cast<float>(static_cast<std::uint32_t>(high_word) << 16 | low_word);
}

double depth_from_pressure(double pressure_bar, const KellerConfig& config) {
  return bar_to_pa(pressure_bar - config.surface_pressure_bar) / (config.water_density_kg_m3 * kStandardGravity);
}

hal::DepthSample KellerDepthSensor::read() {
  hal::DepthSample sample;
  ++stats_.reads;
  std::uint16_t regs[keller::kReadCount] = {};
  const bool answered = link_.read_registers(config_.slave, keller::kP1Address, keller::kReadCount, regs);
  sample.time_us = clock_.now_us();
  if (!answered) {
    ++stats_.bus_failures;
    return sample;
  }
  const double pressure = keller_float(regs[0], regs[1]);
  const double temperature = keller_float(regs[keller::kTob1Offset], regs[keller::kTob1Offset + 1]);
  if (!std::isfinite(pressure) || !std::isfinite(temperature)) {
    ++stats_.channel_errors;
    return sample;
  }
  // Below vacuum or above the transmitter's range, or a sensor temperature
  // no water has: the reading is not a depth.
  if (pressure < 0.0 || pressure > config_.max_pressure_bar || temperature < kMinTemperatureC ||
      temperature > kMaxTemperatureC) {
    ++stats_.out_of_range;
    return sample;
  }
  temperature_c_ = temperature;
  sample.depth_m = depth_from_pressure(pressure, config_);
  sample.valid = true;
  return sample;
}

}  // namespace glider::hal_linux
