// SPDX-License-Identifier: Apache-2.0
#pragma once
// Depth from a Keller Series 30 class pressure transmitter (e.g. PA-33X)
// over Modbus RTU, through the project's bounded ModbusLink. Registers used
// (Keller "Communication protocol Serie30", Process Value Read Range 0x000x,
// holding registers, function 3; each value an IEEE-754 float in two
// registers, high word first; a channel error reads NaN, over/underflow +-inf):
//   0x0002-0x0003  P1    pressure of sensor 1, bar
//   0x0008-0x0009  TOB1  temperature of sensor 1, degC (logged, range-checked)
// One read of 8 registers from 0x0002 takes both. See boards/serial_sensors.md.
#include <cstdint>

#include "glider/hal/clock.hpp"
#include "glider/hal/depth_sensor.hpp"
#include "glider/hal_linux/modbus_link.hpp"

namespace glider::hal_linux {

namespace keller {
constexpr int kP1Address = 0x0002;
constexpr int kReadCount = 8;  // P1, P2, T, TOB1
constexpr int kTob1Offset = 6;
}  // namespace keller

struct KellerConfig {
  int slave = 1;
  // Pressure that reads as 0 m: the atmosphere for an absolute transmitter
  // (PAA), 0 for a gauge one (PR) vented to the atmosphere.
  double surface_pressure_bar = 1.01325;
  double water_density_kg_m3 = 1025.0;
  double max_pressure_bar = 30.0;  // the transmitter's range: above it a reading is rejected
};

struct KellerStats {
  std::uint64_t reads = 0;
  std::uint64_t bus_failures = 0;
  std::uint64_t channel_errors = 0;  // NaN or +-inf from the transmitter
  std::uint64_t out_of_range = 0;
};

// The IEEE-754 float of two Keller registers (high word first).
float keller_float(std::uint16_t high_word, std::uint16_t low_word);
// Depth in m (positive down) of an absolute or gauge pressure, hydrostatic.
double depth_from_pressure(double pressure_bar, const KellerConfig& config);

class KellerDepthSensor final : public hal::DepthSensor {
 public:
  KellerDepthSensor(ModbusLink& link, const KellerConfig& config, const hal::Clock& clock)
      : link_(link), config_(config), clock_(clock) {}
  hal::DepthSample read() override;

  double last_temperature_c() const { return temperature_c_; }
  const KellerStats& stats() const { return stats_; }

 private:
  ModbusLink& link_;
  KellerConfig config_;
  const hal::Clock& clock_;
  double temperature_c_ = 0.0;
  KellerStats stats_;
};

}  // namespace glider::hal_linux
