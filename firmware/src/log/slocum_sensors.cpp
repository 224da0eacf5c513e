// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/slocum_sensors.hpp"

namespace glider::fw {

std::optional<std::size_t> slocum_flight_sensor(std::string_view name) {
  for (std::size_t i = 0; i < kSlocumFlightSensors.size(); ++i) {
    if (kSlocumFlightSensors[i].name == name) return i;
  }
  return std::nullopt;
}

void slocum_flight_values(const hal::FlightLogRecord& record, hal::Micros time_us, double* out) {
  out[0] = static_cast<double>(time_us) / static_cast<double>(hal::kMicrosPerSecond);
  for (std::size_t i = 1; i < hal::kLogColumns.size(); ++i) out[i] = hal::kLogColumns[i].value(record);
}

}  // namespace glider::fw
