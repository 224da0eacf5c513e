// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/config/flight_config_file.hpp"

#include "glider/units.hpp"

#include <limits>
#include <numbers>
#include <string>

namespace glider::fw {
namespace {

using config::Range;

// Physical ranges: a SLOCUM-class glider (1000 m hull at most, a +-1000 cc
// pump at most, a battery slide of a few inches, missions up to two years).
// Signs and orderings (dive pitch < 0, climb above dive...) are validate()'s.
constexpr Range kDepth{0.0, 1500.0, "m"};
// At the surface the depth sensor reads ~0 m plus its noise and the hull's
// draught: a threshold at 0 is never crossed reliably (the surface is never
// detected and the mission ends in an overtime abort), so the range says why.
constexpr Range kSurfacedDepth{0.3, 10.0, "m (at least 0.3 m: the depth sensor never reads 0 at the surface)"};
constexpr Range kPumpCc{-1000.0, 1000.0, "cc"};
constexpr Range kPitchDeg{-80.0, 80.0, "deg"};
constexpr Range kDuration{1.0, 2.0 * 366.0 * 86400.0, "s"};
constexpr Range kSlideIn{-5.0, 5.0, "in"};
constexpr Range kSettledCc{0.0, 100.0, "cc"};
constexpr Range kGain{0.0, 100.0, ""};
constexpr Range kDeadbandIn{0.0, 1.0, "in"};
constexpr Range kSafetyTime{0.1, 3600.0, "s"};
constexpr std::int64_t kMaxYos = 1'000'000;

const std::vector<config::KeyRange>& limits() {
  static const std::vector<config::KeyRange> table{
      {"mission.dive_to_m", kDepth},
      {"mission.climb_to_m", kDepth},
      {"mission.surfaced_depth_m", kSurfacedDepth},
      {"mission.dive_ballast_cc", kPumpCc},
      {"mission.climb_ballast_cc", kPumpCc},
      {"mission.dive_pitch_deg", kPitchDeg},
      {"mission.climb_pitch_deg", kPitchDeg},
      {"mission.max_depth_m", kDepth},
      {"mission.max_duration_s", kDuration},
      {"limits.ballast_min_cc", kPumpCc},
      {"limits.ballast_max_cc", kPumpCc},
      {"limits.battery_min_in", kSlideIn},
      {"limits.battery_max_in", kSlideIn},
      {"limits.ballast_settled_cc", kSettledCc},
      {"pitch_servo.kp_in_per_rad", kGain},
      {"pitch_servo.ki_in_per_rad_s", kGain},
      {"pitch_servo.dive_battpos_in", kSlideIn},
      {"pitch_servo.climb_battpos_in", kSlideIn},
      {"pitch_servo.battery_deadband_in", kDeadbandIn},
      {"safety.sensor_timeout_s", kSafetyTime},
      {"safety.depth_rate_filter_s", kSafetyTime},
  };
  return table;
}

const Range& range_of(std::string_view key) { return config::range_of(limits(), key); }

double required(const config::TomlDocument& doc, const char* key) { return doc.number(key, range_of(key)); }
double optional(const config::TomlDocument& doc, const char* key, double fallback) {
  return doc.number_or(key, fallback, range_of(key));
}

}  // namespace

std::vector<config::KeyRange> flight_config_limits() {
  std::vector<config::KeyRange> out = limits();
  out.push_back({"mission.yos", {1.0, static_cast<double>(kMaxYos), ""}});
  return out;
}

FlightSoftwareConfig read_flight_config(const config::TomlDocument& doc) {
  FlightSoftwareConfig c;
  YoMissionConfig& m = c.mission;
  m.dive_to_m = required(doc, "mission.dive_to_m");
  m.climb_to_m = required(doc, "mission.climb_to_m");
  m.yos = static_cast<std::int32_t>(doc.integer("mission.yos", 1, kMaxYos));
  m.surfaced_depth_m = optional(doc, "mission.surfaced_depth_m", m.surfaced_depth_m);
  m.dive_ballast_cc = required(doc, "mission.dive_ballast_cc");
  m.climb_ballast_cc = required(doc, "mission.climb_ballast_cc");
  m.dive_pitch_rad = deg_to_rad(required(doc, "mission.dive_pitch_deg"));
  m.climb_pitch_rad = deg_to_rad(required(doc, "mission.climb_pitch_deg"));
  m.max_depth_m = required(doc, "mission.max_depth_m");
  m.max_duration_s = required(doc, "mission.max_duration_s");
  doc.string_or("mission.name", "");

  ActuatorLimits& l = c.limits;
  l.ballast_min_cc = optional(doc, "limits.ballast_min_cc", l.ballast_min_cc);
  l.ballast_max_cc = optional(doc, "limits.ballast_max_cc", l.ballast_max_cc);
  l.battery_min_in = optional(doc, "limits.battery_min_in", l.battery_min_in);
  l.battery_max_in = optional(doc, "limits.battery_max_in", l.battery_max_in);
  l.ballast_settled_cc = optional(doc, "limits.ballast_settled_cc", l.ballast_settled_cc);

  c.pitch_kp_in_per_rad = optional(doc, "pitch_servo.kp_in_per_rad", c.pitch_kp_in_per_rad);
  c.pitch_ki_in_per_rad_s = optional(doc, "pitch_servo.ki_in_per_rad_s", c.pitch_ki_in_per_rad_s);
  c.dive_battpos_in = optional(doc, "pitch_servo.dive_battpos_in", c.dive_battpos_in);
  c.climb_battpos_in = optional(doc, "pitch_servo.climb_battpos_in", c.climb_battpos_in);
  c.battery_deadband_in = optional(doc, "pitch_servo.battery_deadband_in", c.battery_deadband_in);

  c.sensor_timeout_s = optional(doc, "safety.sensor_timeout_s", c.sensor_timeout_s);
  c.depth_rate_filter_s = optional(doc, "safety.depth_rate_filter_s", c.depth_rate_filter_s);

  const char* problem = validate(c);
  if (problem[0] != '\0') {
    throw config::ConfigError(doc.source() + ": mission refused: " + problem);
  }
  return c;
}

}  // namespace glider::fw
