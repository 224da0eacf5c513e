// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/flight_software.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "glider/firmware/geo.hpp"

namespace glider::fw {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The HAL's contract (attitude_sensor.hpp): Euler angles, pitch within +-90 deg,
// roll within +-180, heading in [0, 360) - what a compass can report. A value
// outside is a broken driver or sensor, not an attitude (NaN fails every test).
bool attitude_in_range(const hal::AttitudeSample& a) {
  constexpr double kRoundOff = 1e-9;  // degrees converted to radians at the edges
  constexpr double kHalfPi = std::numbers::pi / 2.0 + kRoundOff;
  constexpr double kPi = std::numbers::pi + kRoundOff;
  constexpr double kTwoPi = 2.0 * std::numbers::pi + kRoundOff;
  return a.pitch_rad >= -kHalfPi && a.pitch_rad <= kHalfPi && a.roll_rad >= -kPi && a.roll_rad <= kPi &&
         a.heading_rad >= -kRoundOff && a.heading_rad < kTwoPi;
}

bool is_fresh(hal::Micros now_us, hal::Micros sample_us, double timeout_s) {
  return hal::to_seconds(now_us - sample_us) <= timeout_s;
}

}  // namespace

const char* validate(const FlightSoftwareConfig& c) {
  const char* mission = validate(c.mission);
  if (mission[0] != '\0') return mission;
  const ActuatorLimits& l = c.limits;
  if (!(l.ballast_min_cc < 0.0 && l.ballast_max_cc > 0.0)) return "ballast limits must bracket 0";
  if (!(l.battery_min_in < l.battery_max_in)) return "battery_min_in must be below battery_max_in";
  if (c.mission.dive_ballast_cc < l.ballast_min_cc || c.mission.climb_ballast_cc > l.ballast_max_cc) {
    return "mission ballast outside the pump's limits";
  }
  if (c.dive_battpos_in < l.battery_min_in || c.dive_battpos_in > l.battery_max_in ||
      c.climb_battpos_in < l.battery_min_in || c.climb_battpos_in > l.battery_max_in) {
    return "initial battery positions outside the slide's limits";
  }
  if (!(c.pitch_kp_in_per_rad >= 0.0 && c.pitch_ki_in_per_rad_s >= 0.0)) return "pitch gains must be >= 0";
  if (!(c.sensor_timeout_s > 0.0)) return "sensor_timeout_s must be positive";
  if (!(c.depth_rate_filter_s > 0.0)) return "depth_rate_filter_s must be positive";
  if (!(c.battery_deadband_in >= 0.0)) return "battery_deadband_in must be >= 0";
  const MissionPlan& p = c.plan;
  if (p.waypoint_count < 0 || p.waypoint_count > static_cast<std::int32_t>(kMaxWaypoints)) {
    return "waypoint count out of range";
  }
  if (p.waypoint_count > 0 && !(p.waypoint_radius_m > 0.0)) return "waypoint radius must be positive";
  if (p.waypoint_count > 0 && c.mission.start_at_launch) {
    return "a mission with waypoints must wait at the surface for a GPS fix (start_at_launch false)";
  }
  if (p.legs_to_run == 0 || p.legs_to_run < kLegsOnce) return "legs_to_run must be > 0, -1 (loop) or -2 (once)";
  if (!(p.gps_wait_s >= 0.0 && p.surface_dwell_s >= 0.0)) return "surface waits must be >= 0";
  const HeadingControlConfig& h = c.heading;
  if (!(h.fin_max_rad > 0.0 && h.fin_rate_rad_s > 0.0 && h.delay_s >= 0.0)) {
    return "heading control: fin limit and rate must be positive, delay >= 0";
  }
  if (!(c.aborts.battery_capacity_amphr > 0.0)) return "battery capacity must be positive";
  return "";
}

FlightSoftware::FlightSoftware(const hal::Hal& hal, const FlightSoftwareConfig& config)
    : hal_(hal),
      config_(config),
      mission_(config.mission),
      navigator_(config.plan, config.dead_reckoning, config.aborts.max_wpt_distance_m),
      abort_monitor_(config.aborts),
      guard_({config.limits.ballast_min_cc, config.limits.ballast_max_cc, config.limits.battery_min_in,
              config.limits.battery_max_in, config.heading.fin_max_rad}),
      heading_(config.heading),
      pitch_servo_(PiGains{config.pitch_kp_in_per_rad, config.pitch_ki_in_per_rad_s, config.limits.battery_min_in,
                           config.limits.battery_max_in}),
      dive_trim_in_(config.dive_battpos_in),
      climb_trim_in_(config.climb_battpos_in) {}

void FlightSoftware::update_depth_rate(const hal::DepthSample& depth) {
  if (have_depth_ && depth.time_us > prev_depth_time_us_) {
    const double dt = hal::to_seconds(depth.time_us - prev_depth_time_us_);
    const double raw = (depth.depth_m - prev_depth_m_) / dt;
    if (have_depth_rate_) {
      const double blend = dt / (config_.depth_rate_filter_s + dt);
      depth_rate_m_s_ += blend * (raw - depth_rate_m_s_);
    } else {
      depth_rate_m_s_ = raw;
      have_depth_rate_ = true;
    }
  }
  prev_depth_m_ = depth.depth_m;
  prev_depth_time_us_ = depth.time_us;
}

double FlightSoftware::battery_command(const MissionOutputs& mission, double pitch_rad, double ballast_cc,
                                       double dt_s) {
  const bool diving = mission.phase == Phase::kDive;
  if (mission.phase == Phase::kAbort) {
    return config_.limits.battery_min_in;  // full aft: nose up
  }
  if (!std::isnan(mission.battery_in)) {
    return mission.battery_in;  // pump-only pitch: the battery sits where the mission says
  }
  if (!mission.pitch_control) {
    return battery_cmd_in_;  // hold
  }
  if (mission.phase_changed) {
    // Remember where the servo settled in the glide that just ended and start
    // the new glide from what this direction needed last time.
    if (servo_phase_ == Phase::kDive) {
      dive_trim_in_ = pitch_servo_.output();
    } else if (servo_phase_ == Phase::kClimb) {
      climb_trim_in_ = pitch_servo_.output();
    }
    servo_phase_ = mission.phase;
    pitch_servo_.reset(diving ? dive_trim_in_ : climb_trim_in_);
    return pitch_servo_.output();
  }
  const bool pump_settled = std::abs(ballast_cc - mission.ballast_cc) <= config_.limits.ballast_settled_cc;
  if (!pump_settled || dt_s <= 0.0) {
    return pitch_servo_.output();
  }
  // Battery forward pitches the nose down: nose too high (positive error)
  // needs more forward battery, i.e. a larger output.
  const double wanted = pitch_servo_.update(pitch_rad - mission.pitch_target_rad, dt_s);
  // Every slide move costs energy: a change smaller than the deadband is
  // not made (the servo's integrator keeps the difference and moves the
  // slide once it has grown past it). Saturated commands always go out.
  const bool at_limit = wanted <= config_.limits.battery_min_in || wanted >= config_.limits.battery_max_in;
  if (!at_limit && std::abs(wanted - battery_cmd_in_) < config_.battery_deadband_in) return battery_cmd_in_;
  return wanted;
}

double FlightSoftware::fin_command(const NavigatorOutputs& nav, double dt_s) {
  const bool gliding = last_.phase == Phase::kDive || last_.phase == Phase::kClimb;
  if (!gliding || !std::isfinite(nav.heading_target_rad) || !have_attitude_) {
    heading_.centre();  // at the surface, in an abort, or without a heading to fly
    return 0.0;
  }
  heading_.select_glide(last_.phase == Phase::kDive);
  return heading_.update(attitude_.heading_rad, nav.heading_target_rad, dt_s, navigator_.speed_m_s());
}

// --- sensors: take only valid, finite values; remember when they were seen.
FlightSoftware::CycleReadings FlightSoftware::read_sensors(hal::Micros now_us) {
  CycleReadings in;
  in.depth = hal_.depth.read();
  in.depth_valid = in.depth.valid && std::isfinite(in.depth.depth_m);
  if (in.depth_valid) {
    update_depth_rate(in.depth);
    depth_m_ = in.depth.depth_m;
    depth_time_us_ = in.depth.time_us;
    have_depth_ = true;
  }
  in.attitude = hal_.attitude.read();
  in.attitude_valid = in.attitude.valid && attitude_in_range(in.attitude);
  if (in.attitude_valid) {
    attitude_ = in.attitude;
    have_attitude_ = true;
  }
  in.pump = hal_.pump.read_volume_cc();
  in.battery = hal_.battery.read_position_in();
  in.fin = hal_.rudder.read_angle_rad();
  in.pump_ok = in.pump.valid && !in.pump.fault && std::isfinite(in.pump.position);
  in.battery_ok = in.battery.valid && !in.battery.fault && std::isfinite(in.battery.position);
  in.fin_ok = in.fin.valid && !in.fin.fault && std::isfinite(in.fin.position);
  in.fix = hal_.gps.read();
  in.leak = hal_.leak.read();
  in.leak_ok = in.leak.valid && is_fresh(now_us, in.leak.time_us, config_.sensor_timeout_s);
  in.power = hal_.power.read();
  in.power_ok = in.power.valid && std::isfinite(in.power.charge_used_amphr) &&
                std::isfinite(in.power.battery_voltage_v) &&
                is_fresh(now_us, in.power.time_us, config_.sensor_timeout_s);
  in.depth_ok = have_depth_ && is_fresh(now_us, depth_time_us_, config_.sensor_timeout_s);
  in.attitude_ok = have_attitude_ && is_fresh(now_us, attitude_.time_us, config_.sensor_timeout_s);
  return in;
}

// --- navigation, on last cycle's vertical state: it decides this cycle's segment start.
NavigatorOutputs FlightSoftware::navigate(hal::Micros now_us, const CycleReadings& in) {
  NavigatorInputs nav_in;
  nav_in.now_us = now_us;
  nav_in.phase = last_.phase;
  nav_in.segment_complete = last_.segment_complete;
  nav_in.attitude_ok = in.attitude_ok;
  nav_in.pitch_rad = attitude_.pitch_rad;
  nav_in.heading_rad = attitude_.heading_rad;
  nav_in.depth_rate_ok = have_depth_rate_ && in.depth_ok;
  nav_in.depth_rate_m_s = depth_rate_m_s_;
  nav_in.fix = in.fix;
  nav_in.hold_at_surface = surface_hold_;
  nav_in.resume_now = resume_requested_;
  resume_requested_ = false;
  const NavigatorOutputs nav = navigator_.update(nav_in);
  if (nav.start_segment) mission_.start_segment();
  if (nav.mission_complete) mission_over_ = true;
  return nav;
}

bool FlightSoftware::restart_mission() {
  if (!ended_by_operator_ || !mission_over_ || last_.phase == Phase::kAbort) return false;
  mission_over_ = false;
  ended_by_operator_ = false;
  return true;
}

// --- abort checks beyond the yo's envelope.
AbortCause FlightSoftware::check_aborts(hal::Micros now_us, const CycleReadings& in) {
  AbortMonitorInputs checks;
  checks.now_us = now_us;
  checks.phase = last_.phase;
  checks.depth_ok = in.depth_ok;
  checks.depth_m = depth_m_;
  checks.depth_rate_ok = have_depth_rate_ && in.depth_ok;
  checks.depth_rate_m_s = depth_rate_m_s_;
  checks.gliding = (last_.phase == Phase::kDive || last_.phase == Phase::kClimb) && in.pump_ok &&
                   std::abs(in.pump.position - last_.ballast_cc) <= config_.limits.ballast_settled_cc;
  checks.leak_ok = in.leak_ok;
  checks.leak = in.leak.active;
  checks.power_ok = in.power_ok;
  checks.charge_used_amphr = in.power.charge_used_amphr;
  return abort_monitor_.check(checks);
}

// --- the yo mission: this cycle's phase and targets.
void FlightSoftware::run_mission(hal::Micros now_us, const CycleReadings& in, const NavigatorOutputs& nav,
                                 AbortCause monitored) {
  MissionInputs mission_in;
  mission_in.now_us = now_us;
  mission_in.depth_m = depth_m_;
  mission_in.depth_ok = in.depth_ok;
  mission_in.attitude_ok = in.attitude_ok;
  mission_in.actuator_fault = !in.pump_ok || !in.battery_ok || !in.fin_ok;
  mission_in.external_abort = monitored != AbortCause::kNone ? monitored : nav.abort;
  mission_in.surface_requested = nav.surface_requested;
  mission_in.mission_over = mission_over_;
  last_ = mission_.update(mission_in);
}

// --- control and actuators: a command goes out only when it changes.
FlightSoftware::CycleCommands FlightSoftware::command_actuators(const CycleReadings& in, const NavigatorOutputs& nav,
                                                                double dt_s) {
  const bool aborting = last_.phase == Phase::kAbort;
  CycleCommands c;
  c.ballast_cc = guard_.ballast_cc(aborting ? config_.limits.ballast_max_cc : last_.ballast_cc);
  c.battery_in = guard_.battery_in(
      battery_command(last_, attitude_.pitch_rad, in.pump_ok ? in.pump.position : ballast_cmd_cc_, dt_s));
  if (!commanded_ || c.ballast_cc != ballast_cmd_cc_) {
    hal_.pump.command_volume_cc(c.ballast_cc);
  }
  if (!commanded_ || c.battery_in != battery_cmd_in_) {
    hal_.battery.command_position_in(c.battery_in);
  }
  c.fin_rad = guard_.fin_rad(aborting ? 0.0 : fin_command(nav, dt_s));
  if (!commanded_ || c.fin_rad != fin_cmd_rad_) {
    hal_.rudder.command_angle_rad(c.fin_rad);
  }
  // The abort sequence drops the emergency weight where one is fitted
  // (once: the burn wire is commanded and left on).
  if (aborting && config_.aborts.drop_weight_fitted && !drop_weight_released_) {
    drop_weight_released_ = hal_.drop_weight.set(true);
  }
  ballast_cmd_cc_ = c.ballast_cc;
  battery_cmd_in_ = c.battery_in;
  fin_cmd_rad_ = c.fin_rad;
  commanded_ = true;
  return c;
}

// --- the log record (hal::kLogColumns): NaN where there is no valid value.
void FlightSoftware::log_record(hal::Micros now_us, const CycleReadings& in, const NavigatorOutputs& nav,
                                const CycleCommands& commands) {
  const bool aborting = last_.phase == Phase::kAbort;
  hal::FlightLogRecord row;
  row.time_us = now_us;
  row.m_depth = in.depth_valid ? in.depth.depth_m : kNaN;
  row.m_depth_rate = have_depth_rate_ && in.depth_valid ? depth_rate_m_s_ : kNaN;
  row.m_pitch = in.attitude_valid ? in.attitude.pitch_rad : kNaN;
  row.m_roll = in.attitude_valid ? in.attitude.roll_rad : kNaN;
  row.m_heading = in.attitude_valid ? in.attitude.heading_rad : kNaN;
  row.m_ballast_pumped = in.pump_ok ? in.pump.position : kNaN;
  row.c_ballast_pumped = commands.ballast_cc;
  row.m_battpos = in.battery_ok ? in.battery.position : kNaN;
  row.c_battpos = commands.battery_in;
  row.c_pitch = last_.pitch_control ? last_.pitch_target_rad : kNaN;
  row.m_depth_state = static_cast<std::int32_t>(last_.phase);
  row.x_yo_count = last_.yos_completed;
  row.x_abort_cause = static_cast<std::int32_t>(last_.abort_cause);
  row.x_loop_overruns = executive_ != nullptr ? executive_->stats().overruns : 0;
  row.c_heading = std::isfinite(nav.heading_target_rad) && !aborting ? nav.heading_target_rad : kNaN;
  row.m_fin = in.fin_ok ? in.fin.position : kNaN;
  row.c_fin = commands.fin_rad;
  row.m_gps_lat = nav.new_fix ? degrees_to_nmea(in.fix.latitude_deg) : kNaN;
  row.m_gps_lon = nav.new_fix ? degrees_to_nmea(in.fix.longitude_deg) : kNaN;
  row.m_gps_utc_s = nav.new_fix ? in.fix.utc_time_of_day_s : kNaN;
  const bool have_position = navigator_.have_position();
  row.m_lat = have_position ? degrees_to_nmea(navigator_.dr_position().lat_deg) : kNaN;
  row.m_lon = have_position ? degrees_to_nmea(navigator_.dr_position().lon_deg) : kNaN;
  row.m_water_vx = navigator_.have_current() ? navigator_.current_m_s().east_m : kNaN;
  row.m_water_vy = navigator_.have_current() ? navigator_.current_m_s().north_m : kNaN;
  row.m_leakdetect = in.leak_ok ? (in.leak.active ? 1 : 0) : -1;
  row.m_coulomb_amphr_total = in.power_ok ? in.power.charge_used_amphr : kNaN;
  row.m_battery = in.power_ok ? in.power.battery_voltage_v : kNaN;
  row.x_waypoint = navigator_.active_waypoint();
  row.x_waypoints_reached = navigator_.waypoints_reached();
  row.x_segment = navigator_.segments();
  row.x_dr_error_m = nav.surfacing.valid ? nav.surfacing.dr_error_m : kNaN;
  row.x_dr_distance_m = nav.surfacing.valid ? nav.surfacing.distance_through_water_m : kNaN;
  row.x_mission_complete = complete() ? 1 : 0;
  if (!hal_.log.write(row)) {
    ++log_rows_lost_;
  }
}

void FlightSoftware::run(hal::Micros now_us) {
  const double dt_s = has_run_ ? hal::to_seconds(now_us - last_run_us_) : 0.0;
  last_run_us_ = now_us;
  has_run_ = true;
  const CycleReadings readings = read_sensors(now_us);
  const NavigatorOutputs nav = navigate(now_us, readings);
  const AbortCause monitored = check_aborts(now_us, readings);
  run_mission(now_us, readings, nav, monitored);
  const CycleCommands commands = command_actuators(readings, nav, dt_s);
  log_record(now_us, readings, nav, commands);
}

}  // namespace glider::fw
