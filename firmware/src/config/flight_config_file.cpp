// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/config/flight_config_file.hpp"

#include "glider/units.hpp"

#include <limits>
#include <numbers>
#include <string>

namespace glider::fw {
FlightSoftwareConfig read_flight_config(const config::TomlDocument& doc) {
  FlightSoftwareConfig c;
  YoMissionConfig& m = c.mission;
  m.dive_to_m = doc.number("mission.dive_to_m");
  m.climb_to_m = doc.number("mission.climb_to_m");
  const std::int64_t yos = doc.integer("mission.yos");
  if (yos < 1 || yos > std::numeric_limits<std::int32_t>::max()) {
    doc.fail("mission.yos", "must be a positive count");
  }
  m.yos = static_cast<std::int32_t>(yos);
  m.surfaced_depth_m = doc.number_or("mission.surfaced_depth_m", m.surfaced_depth_m);
  m.dive_ballast_cc = doc.number("mission.dive_ballast_cc");
  m.climb_ballast_cc = doc.number("mission.climb_ballast_cc");
  m.dive_pitch_rad = deg_to_rad(doc.number("mission.dive_pitch_deg"));
  m.climb_pitch_rad = deg_to_rad(doc.number("mission.climb_pitch_deg"));
  m.max_depth_m = doc.number("mission.max_depth_m");
  m.max_duration_s = doc.number("mission.max_duration_s");
  doc.string_or("mission.name", "");

  ActuatorLimits& l = c.limits;
  l.ballast_min_cc = doc.number_or("limits.ballast_min_cc", l.ballast_min_cc);
  l.ballast_max_cc = doc.number_or("limits.ballast_max_cc", l.ballast_max_cc);
  l.battery_min_in = doc.number_or("limits.battery_min_in", l.battery_min_in);
  l.battery_max_in = doc.number_or("limits.battery_max_in", l.battery_max_in);
  l.ballast_settled_cc = doc.number_or("limits.ballast_settled_cc", l.ballast_settled_cc);

  c.pitch_kp_in_per_rad = doc.number_or("pitch_servo.kp_in_per_rad", c.pitch_kp_in_per_rad);
  c.pitch_ki_in_per_rad_s = doc.number_or("pitch_servo.ki_in_per_rad_s", c.pitch_ki_in_per_rad_s);
  c.dive_battpos_in = doc.number_or("pitch_servo.dive_battpos_in", c.dive_battpos_in);
  c.climb_battpos_in = doc.number_or("pitch_servo.climb_battpos_in", c.climb_battpos_in);
  c.battery_deadband_in = doc.number_or("pitch_servo.battery_deadband_in", c.battery_deadband_in);

  c.sensor_timeout_s = doc.number_or("safety.sensor_timeout_s", c.sensor_timeout_s);
  c.depth_rate_filter_s = doc.number_or("safety.depth_rate_filter_s", c.depth_rate_filter_s);

  const char* problem = validate(c);
  if (problem[0] != '\0') {
    throw config::ConfigError(doc.source() + ": mission refused: " + problem);
  }
  return c;
}

}  // namespace glider::fw
