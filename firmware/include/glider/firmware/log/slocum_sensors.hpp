// SPDX-License-Identifier: Apache-2.0
#pragma once
// The firmware's log record as Slocum sensors (docs/slocum-binary.md,
// "Writing"): one sensor per column of the flight log's schema
// (hal::kLogColumns), same name and order, with the unit word and the stored
// size a Slocum flight computer uses for that sensor (taken from a real
// glider's sensor list, tests/data/real/dbd/comet-2019/cac/1f35be3b.cac):
// times and positions 8-byte doubles, measurements 4-byte floats, small
// enums 1-byte integers. The firmware's own counters (x_*) are 4-byte floats
// like Slocum's counters (m_tot_num_inflections): exact up to 2^24.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "glider/hal/log_record.hpp"

namespace glider::fw {

struct SlocumSensor {
  std::string_view name;
  std::string_view unit;  // Slocum's unit word (timestamp, m, rad, lat, enum, nodim, ...)
  std::uint8_t bytes;     // 1, 2: signed integer; 4: float; 8: double
};

inline constexpr std::array kSlocumFlightSensors{
    SlocumSensor{"m_present_time", "timestamp", 8},
    SlocumSensor{"m_depth", "m", 4},
    SlocumSensor{"m_depth_rate", "m/s", 4},
    SlocumSensor{"m_pitch", "rad", 4},
    SlocumSensor{"m_roll", "rad", 4},
    SlocumSensor{"m_heading", "rad", 4},
    SlocumSensor{"m_ballast_pumped", "cc", 4},
    SlocumSensor{"c_ballast_pumped", "cc", 4},
    SlocumSensor{"m_battpos", "in", 4},
    SlocumSensor{"c_battpos", "in", 4},
    SlocumSensor{"c_pitch", "rad", 4},
    SlocumSensor{"m_depth_state", "enum", 1},
    SlocumSensor{"x_yo_count", "nodim", 4},
    SlocumSensor{"x_abort_cause", "enum", 1},
    SlocumSensor{"x_loop_overruns", "nodim", 4},
    SlocumSensor{"c_heading", "rad", 4},
    SlocumSensor{"m_fin", "rad", 4},
    SlocumSensor{"c_fin", "rad", 4},
    SlocumSensor{"m_gps_lat", "lat", 8},
    SlocumSensor{"m_gps_lon", "lon", 8},
    SlocumSensor{"m_gps_utc_s", "sec", 8},
    SlocumSensor{"m_lat", "lat", 8},
    SlocumSensor{"m_lon", "lon", 8},
    SlocumSensor{"m_water_vx", "m/s", 4},
    SlocumSensor{"m_water_vy", "m/s", 4},
    SlocumSensor{"m_leakdetect", "enum", 1},
    SlocumSensor{"m_coulomb_amphr_total", "amp-hrs", 4},
    SlocumSensor{"m_battery", "volts", 4},
    SlocumSensor{"x_waypoint", "nodim", 4},
    SlocumSensor{"x_waypoints_reached", "nodim", 4},
    SlocumSensor{"x_segment", "nodim", 4},
    SlocumSensor{"x_dr_error_m", "m", 4},
    SlocumSensor{"x_dr_distance_m", "m", 4},
    SlocumSensor{"x_mission_complete", "bool", 1},
};

inline constexpr std::size_t kSlocumFlightSensorCount = kSlocumFlightSensors.size();

// The table is the log schema, column for column.
consteval bool slocum_sensors_match_schema() {
  if (kSlocumFlightSensors.size() != hal::kLogColumns.size()) return false;
  for (std::size_t i = 0; i < kSlocumFlightSensors.size(); ++i) {
    if (kSlocumFlightSensors[i].name != hal::kLogColumns[i].name) return false;
    const std::uint8_t b = kSlocumFlightSensors[i].bytes;
    if (b != 1 && b != 2 && b != 4 && b != 8) return false;
  }
  return true;
}
static_assert(slocum_sensors_match_schema(), "kSlocumFlightSensors must follow hal::kLogColumns");

// Index of `name` in kSlocumFlightSensors, or nullopt.
std::optional<std::size_t> slocum_flight_sensor(std::string_view name);

// The record's values in sensor order, m_present_time as `time_us` in
// seconds (the correctly rounded quotient: the value the CSV's exact decimal
// text reads back as). `out` holds kSlocumFlightSensorCount values.
void slocum_flight_values(const hal::FlightLogRecord& record, hal::Micros time_us, double* out);

}  // namespace glider::fw
