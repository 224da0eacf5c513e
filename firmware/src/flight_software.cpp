#include "glider/firmware/flight_software.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glider::fw {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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
  return "";
}

FlightSoftware::FlightSoftware(const hal::Hal& hal, const FlightSoftwareConfig& config)
    : hal_(hal),
      config_(config),
      mission_(config.mission),
      pitch_servo_(PiGains{config.pitch_kp_in_per_rad, config.pitch_ki_in_per_rad_s,
                           config.limits.battery_min_in, config.limits.battery_max_in}),
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

double FlightSoftware::battery_command(const MissionOutputs& mission, double pitch_rad,
                                       double ballast_cc, double dt_s) {
  const bool diving = mission.phase == Phase::kDive;
  if (mission.phase == Phase::kAbort) {
    return config_.limits.battery_min_in;  // full aft: nose up
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
  return pitch_servo_.update(pitch_rad - mission.pitch_target_rad, dt_s);
}

void FlightSoftware::run(hal::Micros now_us) {
  const double dt_s = has_run_ ? hal::to_seconds(now_us - last_run_us_) : 0.0;
  last_run_us_ = now_us;
  has_run_ = true;

  // --- sensors: take only valid, finite values; remember when they were seen
  const hal::DepthSample depth = hal_.depth.read();
  const bool depth_valid = depth.valid && std::isfinite(depth.depth_m);
  if (depth_valid) {
    update_depth_rate(depth);
    depth_m_ = depth.depth_m;
    depth_time_us_ = depth.time_us;
    have_depth_ = true;
  }
  const hal::AttitudeSample attitude = hal_.attitude.read();
  const bool attitude_valid = attitude.valid && std::isfinite(attitude.pitch_rad) &&
                              std::isfinite(attitude.roll_rad) && std::isfinite(attitude.heading_rad);
  if (attitude_valid) {
    attitude_ = attitude;
    have_attitude_ = true;
  }
  const hal::ActuatorReading pump = hal_.pump.read_volume_cc();
  const hal::ActuatorReading battery = hal_.battery.read_position_in();
  const bool pump_ok = pump.valid && !pump.fault && std::isfinite(pump.position);
  const bool battery_ok = battery.valid && !battery.fault && std::isfinite(battery.position);

  // --- mission
  MissionInputs in;
  in.now_us = now_us;
  in.depth_m = depth_m_;
  in.depth_ok = have_depth_ && is_fresh(now_us, depth_time_us_, config_.sensor_timeout_s);
  in.attitude_ok = have_attitude_ && is_fresh(now_us, attitude_.time_us, config_.sensor_timeout_s);
  in.actuator_fault = !pump_ok || !battery_ok;
  last_ = mission_.update(in);

  // --- control and actuators
  const double ballast_target = last_.phase == Phase::kAbort ? config_.limits.ballast_max_cc : last_.ballast_cc;
  const double battery_target =
      battery_command(last_, attitude_.pitch_rad, pump_ok ? pump.position : ballast_cmd_cc_, dt_s);
  if (!commanded_ || ballast_target != ballast_cmd_cc_) {
    hal_.pump.command_volume_cc(ballast_target);
  }
  if (!commanded_ || battery_target != battery_cmd_in_) {
    hal_.battery.command_position_in(battery_target);
  }
  ballast_cmd_cc_ = ballast_target;
  battery_cmd_in_ = battery_target;
  commanded_ = true;

  // --- log
  hal::FlightLogRecord row;
  row.time_us = now_us;
  row.m_depth = depth_valid ? depth.depth_m : kNaN;
  row.m_depth_rate = have_depth_rate_ && depth_valid ? depth_rate_m_s_ : kNaN;
  row.m_pitch = attitude_valid ? attitude.pitch_rad : kNaN;
  row.m_roll = attitude_valid ? attitude.roll_rad : kNaN;
  row.m_heading = attitude_valid ? attitude.heading_rad : kNaN;
  row.m_ballast_pumped = pump_ok ? pump.position : kNaN;
  row.c_ballast_pumped = ballast_target;
  row.m_battpos = battery_ok ? battery.position : kNaN;
  row.c_battpos = battery_target;
  row.c_pitch = last_.pitch_control ? last_.pitch_target_rad : kNaN;
  row.m_depth_state = static_cast<std::int32_t>(last_.phase);
  row.x_yo_count = last_.yos_completed;
  row.x_abort_cause = static_cast<std::int32_t>(last_.abort_cause);
  row.x_loop_overruns = executive_ != nullptr ? executive_->stats().overruns : 0;
  if (!hal_.log.write(row)) {
    ++log_rows_lost_;
  }
}

}  // namespace glider::fw
