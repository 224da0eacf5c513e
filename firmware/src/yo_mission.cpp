// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/yo_mission.hpp"

#include <cmath>

namespace glider::fw {

const char* to_string(Phase phase) {
  switch (phase) {
    case Phase::kSurface:
      return "surface";
    case Phase::kDive:
      return "dive";
    case Phase::kClimb:
      return "climb";
    case Phase::kAbort:
      return "abort";
  }
  return "?";
}

namespace {

struct CauseName {
  AbortCause cause;
  const char* id;    // one word: log trailer, summary JSON
  const char* text;  // for people
};

constexpr CauseName kCauseNames[] = {
    {AbortCause::kNone, "none", "none"},
    {AbortCause::kOverdepth, "overdepth", "overdepth"},
    {AbortCause::kOvertime, "overtime", "overtime"},
    {AbortCause::kDepthSensor, "depth_sensor", "depth sensor invalid or stale"},
    {AbortCause::kAttitudeSensor, "attitude_sensor", "attitude sensor invalid or stale"},
    {AbortCause::kActuatorFault, "actuator_fault", "actuator fault"},
    {AbortCause::kLeak, "leak", "leak detected"},
    {AbortCause::kLowBattery, "low_battery", "low battery (remaining charge)"},
    {AbortCause::kSameDepth, "samedepth", "stuck at the same depth"},
    {AbortCause::kStalled, "stalled", "stalled"},
    {AbortCause::kWaypointTooFar, "waypoint_too_far", "waypoint too far"},
};

const CauseName* find_cause(AbortCause cause) {
  for (const CauseName& name : kCauseNames) {
    if (name.cause == cause) return &name;
  }
  return nullptr;
}

}  // namespace

const char* cause_id(AbortCause cause) {
  const CauseName* name = find_cause(cause);
  return name != nullptr ? name->id : "unknown";
}

const char* to_string(AbortCause cause) {
  const CauseName* name = find_cause(cause);
  return name != nullptr ? name->text : "?";
}

const char* validate(const YoMissionConfig& c) {
  if (c.yos < 1) return "yos must be at least 1";
  if (!(c.climb_to_m > c.surfaced_depth_m)) return "climb_to_m must be deeper than surfaced_depth_m";
  if (!(c.dive_to_m > c.climb_to_m)) return "dive_to_m must be deeper than climb_to_m";
  if (!(c.max_depth_m > c.dive_to_m)) return "max_depth_m must be deeper than dive_to_m";
  if (!(c.dive_ballast_cc < 0.0)) return "dive_ballast_cc must be negative (heavier)";
  if (!(c.climb_ballast_cc > 0.0)) return "climb_ballast_cc must be positive (lighter)";
  if (!(c.dive_pitch_rad < 0.0)) return "dive pitch must be negative (nose down)";
  if (!(c.climb_pitch_rad > 0.0)) return "climb pitch must be positive (nose up)";
  if (!(c.max_duration_s > 0.0)) return "max_duration_s must be positive";
  if (std::isnan(c.dive_battpos_in) != std::isnan(c.climb_battpos_in)) {
    return "a fixed battery position needs both dive and climb values";
  }
  return "";
}

AbortCause YoMission::check_envelope(const MissionInputs& in) const {
  if (!in.depth_ok) return AbortCause::kDepthSensor;
  if (!in.attitude_ok) return AbortCause::kAttitudeSensor;
  if (in.actuator_fault) return AbortCause::kActuatorFault;
  if (in.depth_m > config_.max_depth_m) return AbortCause::kOverdepth;
  if (hal::to_seconds(in.now_us - start_us_) > config_.max_duration_s) return AbortCause::kOvertime;
  return in.external_abort;
}

void YoMission::enter(Phase phase, MissionOutputs& out) {
  phase_ = phase;
  out.phase_changed = true;
}

MissionOutputs YoMission::update(const MissionInputs& in) {
  MissionOutputs out;
  if (!started_) {
    started_ = true;
    start_us_ = in.now_us;
    if (config_.start_at_launch) {
      enter(Phase::kDive, out);
    } else {
      complete_ = true;  // at the surface, waiting to be sent down
    }
  }
  const bool segment_over = complete_ && phase_ == Phase::kSurface;
  if (start_requested_ && segment_over) {
    complete_ = false;
    final_climb_ = false;
    segment_yos_ = 0;
    enter(Phase::kDive, out);
  }
  start_requested_ = false;

  // The envelope is watched from launch on, at the surface between segments
  // too (a leak or a dead sensor there), but not after the mission is over.
  const bool over = complete_ && (config_.start_at_launch || in.mission_over);
  const bool watching = phase_ != Phase::kAbort && !over;
  if (watching) {
    const AbortCause cause = check_envelope(in);
    if (cause != AbortCause::kNone) {
      abort_cause_ = cause;
      complete_ = false;
      enter(Phase::kAbort, out);
    }
  }

  if (in.surface_requested && (phase_ == Phase::kDive || phase_ == Phase::kClimb) && !final_climb_) {
    final_climb_ = true;
    if (phase_ == Phase::kDive) enter(Phase::kClimb, out);
  }

  switch (phase_) {
    case Phase::kDive:
      if (in.depth_m >= config_.dive_to_m) {
        enter(Phase::kClimb, out);
      }
      break;
    case Phase::kClimb:
      if (!final_climb_ && in.depth_m <= config_.climb_to_m) {
        ++yos_completed_;
        ++segment_yos_;
        if (segment_yos_ < config_.yos) {
          enter(Phase::kDive, out);
        } else {
          final_climb_ = true;  // keep climbing to the surface
        }
      } else if (final_climb_ && in.depth_m <= config_.surfaced_depth_m) {
        complete_ = true;
        enter(Phase::kSurface, out);
      }
      break;
    case Phase::kAbort:
      // Stay in abort; the mission is over once the vehicle is up (a valid
      // shallow depth), otherwise it keeps ascending as far as it knows.
      complete_ = in.depth_ok && in.depth_m <= config_.surfaced_depth_m;
      break;
    case Phase::kSurface:
      break;
  }

  out.phase = phase_;
  out.abort_cause = abort_cause_;
  out.yos_completed = yos_completed_;
  out.complete = complete_;
  out.segment_complete = complete_ && phase_ == Phase::kSurface;
  const bool fixed_battery = !std::isnan(config_.dive_battpos_in);
  switch (phase_) {
    case Phase::kDive:
      out.ballast_cc = config_.dive_ballast_cc;
      out.pitch_target_rad = config_.dive_pitch_rad;
      out.pitch_control = !fixed_battery;
      out.battery_in = config_.dive_battpos_in;
      break;
    case Phase::kClimb:
      out.ballast_cc = config_.climb_ballast_cc;
      out.pitch_target_rad = config_.climb_pitch_rad;
      out.pitch_control = !fixed_battery;
      out.battery_in = config_.climb_battpos_in;
      break;
    case Phase::kSurface:
    case Phase::kAbort:
      // Full buoyancy; the flight software puts the battery aft.
      out.ballast_cc = config_.climb_ballast_cc;
      out.pitch_target_rad = 0.0;
      out.pitch_control = false;
      break;
  }
  return out;
}

}  // namespace glider::fw
