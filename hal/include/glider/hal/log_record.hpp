// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <cstdint>
#include <string_view>

#include "glider/hal/time.hpp"

namespace glider::hal {

// One row of the flight log, as the firmware knows it, in Slocum names and
// units (see docs/flight-log.md). A field the firmware has no valid value for
// this cycle is NaN and is written as an empty CSV field.
struct FlightLogRecord {
  Micros time_us = 0;                 // m_present_time (mission clock)
  double m_depth = 0.0;               // m
  double m_depth_rate = 0.0;          // m/s, + descending
  double m_pitch = 0.0;               // rad
  double m_roll = 0.0;                // rad
  double m_heading = 0.0;             // rad
  double m_ballast_pumped = 0.0;      // cc
  double c_ballast_pumped = 0.0;      // cc
  double m_battpos = 0.0;             // in
  double c_battpos = 0.0;             // in
  double c_pitch = 0.0;               // rad, pitch target of the battery servo
  std::int32_t m_depth_state = 0;     // 1 dive, 2 climb, 3 hover, 0 surface, 99 abort
  std::int32_t x_yo_count = 0;        // completed yos in this mission
  std::int32_t x_abort_cause = 0;     // fw::AbortCause, 0 = none
  std::uint32_t x_loop_overruns = 0;  // executive cycles over budget, cumulative
  double c_heading = 0.0;             // rad, heading target (NaN: no heading control)
  double m_fin = 0.0;                 // rad
  double c_fin = 0.0;                 // rad
  double m_gps_lat = 0.0;             // NMEA ddmm.mmm, a fresh fix this cycle only
  double m_gps_lon = 0.0;
  double m_gps_utc_s = 0.0;  // s of the UTC day the receiver stamped that fix (a system-clock step shows against it)
  double m_lat = 0.0;        // NMEA, dead-reckoned (last fix at the surface)
  double m_lon = 0.0;
  double m_water_vx = 0.0;             // m/s east, depth-averaged current estimate
  double m_water_vy = 0.0;             // m/s north
  std::int32_t m_leakdetect = 0;       // 1 leak, 0 dry, -1 no valid reading
  double m_coulomb_amphr_total = 0.0;  // Ah used
  double m_battery = 0.0;              // V
  std::int32_t x_waypoint = 0;         // index of the active waypoint
  std::int32_t x_waypoints_reached = 0;
  std::int32_t x_segment = 0;    // segments started
  double x_dr_error_m = 0.0;     // |GPS - DR| at the first fix after a segment (NaN otherwise)
  double x_dr_distance_m = 0.0;  // that segment's DR distance through the water
  std::int32_t x_mission_complete = 0;
};

// The flight log's one schema: every firmware column in file order, with its
// unit. The SIL writer, the target writer and the reader
// (tools/files/flightlog/src/columns.cpp) all work from this table, and a test
// checks it against the table in docs/flight-log.md. m_present_time is the
// first column (the writers format it from the row's time); kNumber columns
// are written as the shortest round-trip text (std::to_chars), kInteger ones
// as integers; NaN is an empty field.
enum class LogColumnKind { kTime, kNumber, kInteger };

// A column of a row type `Row`: the firmware's record here, the SIL's
// appended columns in sim_log_columns.hpp (the same mechanism, one schema).
template <typename Row>
struct LogColumnOf {
  std::string_view name;
  std::string_view unit;
  LogColumnKind kind;
  double (*value)(const Row&);  // kNumber/kInteger (integers are exact in a double)
};
using LogColumn = LogColumnOf<FlightLogRecord>;

#define GLIDER_LOG_NUMBER(field, unit)                                                     \
  LogColumn {                                                                              \
#field, unit, LogColumnKind::kNumber, [](const FlightLogRecord& r) { return r.field; } \
  }
#define GLIDER_LOG_INTEGER(field, unit)                                                                          \
  LogColumn {                                                                                                    \
#field, unit, LogColumnKind::kInteger, [](const FlightLogRecord& r) { return static_cast<double>(r.field); } \
  }

inline constexpr std::array kLogColumns{
    LogColumn{"m_present_time", "s", LogColumnKind::kTime, nullptr},
    GLIDER_LOG_NUMBER(m_depth, "m"),
    GLIDER_LOG_NUMBER(m_depth_rate, "m/s"),
    GLIDER_LOG_NUMBER(m_pitch, "rad"),
    GLIDER_LOG_NUMBER(m_roll, "rad"),
    GLIDER_LOG_NUMBER(m_heading, "rad"),
    GLIDER_LOG_NUMBER(m_ballast_pumped, "cc"),
    GLIDER_LOG_NUMBER(c_ballast_pumped, "cc"),
    GLIDER_LOG_NUMBER(m_battpos, "in"),
    GLIDER_LOG_NUMBER(c_battpos, "in"),
    GLIDER_LOG_NUMBER(c_pitch, "rad"),
    GLIDER_LOG_INTEGER(m_depth_state, "enum"),
    GLIDER_LOG_INTEGER(x_yo_count, "count"),
    GLIDER_LOG_INTEGER(x_abort_cause, "enum"),
    GLIDER_LOG_INTEGER(x_loop_overruns, "count"),
    GLIDER_LOG_NUMBER(c_heading, "rad"),
    GLIDER_LOG_NUMBER(m_fin, "rad"),
    GLIDER_LOG_NUMBER(c_fin, "rad"),
    GLIDER_LOG_NUMBER(m_gps_lat, "ddmm.mmmm"),
    GLIDER_LOG_NUMBER(m_gps_lon, "ddmm.mmmm"),
    GLIDER_LOG_NUMBER(m_gps_utc_s, "s"),
    GLIDER_LOG_NUMBER(m_lat, "ddmm.mmmm"),
    GLIDER_LOG_NUMBER(m_lon, "ddmm.mmmm"),
    GLIDER_LOG_NUMBER(m_water_vx, "m/s"),
    GLIDER_LOG_NUMBER(m_water_vy, "m/s"),
    GLIDER_LOG_INTEGER(m_leakdetect, "enum"),
    GLIDER_LOG_NUMBER(m_coulomb_amphr_total, "Ah"),
    GLIDER_LOG_NUMBER(m_battery, "V"),
    GLIDER_LOG_INTEGER(x_waypoint, "index"),
    GLIDER_LOG_INTEGER(x_waypoints_reached, "count"),
    GLIDER_LOG_INTEGER(x_segment, "count"),
    GLIDER_LOG_NUMBER(x_dr_error_m, "m"),
    GLIDER_LOG_NUMBER(x_dr_distance_m, "m"),
    GLIDER_LOG_INTEGER(x_mission_complete, "bool"),
};

#undef GLIDER_LOG_NUMBER
#undef GLIDER_LOG_INTEGER

// Where the firmware hands its log rows. Implementations must not block the
// control loop (SIL: buffered file; Linux: ring buffer drained by a writer).
// Returns false when the row could not be stored (the firmware counts it).
class LogSink {
 public:
  virtual ~LogSink() = default;
  virtual bool write(const FlightLogRecord& record) = 0;
};

}  // namespace glider::hal
