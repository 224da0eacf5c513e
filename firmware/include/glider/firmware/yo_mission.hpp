// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <cstdint>
#include <limits>

#include "glider/hal/time.hpp"

namespace glider::fw {

// Values of m_depth_state as the real Slocum logs them, plus an abort state.
enum class Phase : std::int32_t {
  kSurface = 0,  // at the surface: before the first dive and when complete
  kDive = 1,
  kClimb = 2,
  kAbort = 99,
};

enum class AbortCause : std::int32_t {
  kNone = 0,
  kOverdepth = 1,
  kOvertime = 2,
  kDepthSensor = 3,
  kAttitudeSensor = 4,
  kActuatorFault = 5,
  kLeak = 6,
  kLowBattery = 7,
  kSameDepth = 8,        // abend samedepth_for
  kStalled = 9,          // abend stalled_for
  kWaypointTooFar = 10,  // abend max_wpt_distance
};

const char* to_string(Phase phase);
const char* to_string(AbortCause cause);
// The cause as one word (log trailer, summary JSON; docs/flight-log.md):
// none overdepth overtime depth_sensor attitude_sensor actuator_fault leak
// low_battery samedepth stalled waypoint_too_far. Stable: tools key on it.
const char* cause_id(AbortCause cause);

struct YoMissionConfig {
  double dive_to_m = 50.0;        // inflect to climb at this depth
  double climb_to_m = 5.0;        // inflect to dive at this depth
  std::int32_t yos = 3;           // dive+climb cycles per segment, then surface
  double surfaced_depth_m = 1.0;  // shallower than this counts as surfaced
  double dive_ballast_cc = -250.0;
  double climb_ballast_cc = 250.0;
  double dive_pitch_rad = -0.4537856;  // -26 deg
  double climb_pitch_rad = 0.4537856;  // +26 deg
  // Safety envelope (the abort sequence surfaces the vehicle).
  double max_depth_m = 60.0;
  double max_duration_s = 4.0 * 3600.0;  // infinity: no overtime limit (abend overtime -1)
  // Pump-only pitch (Slocum d_/c_use_pitch 1): the battery sits at these
  // positions (in) instead of servoing the pitch; NaN = pitch servo.
  double dive_battpos_in = std::numeric_limits<double>::quiet_NaN();
  double climb_battpos_in = std::numeric_limits<double>::quiet_NaN();
  // true: the first dive starts at once (a yo-only mission); false: the
  // mission waits at the surface until start_segment() (navigation: GPS first).
  bool start_at_launch = true;
};

// Returns an empty string when the configuration is flyable, otherwise a
// sentence naming the first problem (checked before launch, never in flight).
const char* validate(const YoMissionConfig& config);

struct MissionInputs {
  hal::Micros now_us = 0;
  double depth_m = 0.0;      // last valid depth
  bool depth_ok = false;     // valid and not stale
  bool attitude_ok = false;  // valid and not stale
  bool actuator_fault = false;
  AbortCause external_abort = AbortCause::kNone;  // from the abort monitor or navigation
  bool surface_requested = false;                 // end the segment: finish with a climb to the surface
  bool mission_over = false;                      // navigation has ended the mission (no more checks at the surface)
};

struct MissionOutputs {
  Phase phase = Phase::kSurface;
  AbortCause abort_cause = AbortCause::kNone;
  double ballast_cc = 0.0;
  double pitch_target_rad = 0.0;
  bool pitch_control = false;                                    // false: hold the battery where it is told
  double battery_in = std::numeric_limits<double>::quiet_NaN();  // fixed battery (pump-only pitch), NaN = none
  bool phase_changed = false;                                    // true on the cycle a new phase begins
  bool complete = false;                                         // mission over (surfaced or aborted and up)
  std::int32_t yos_completed = 0;                                // in the whole mission
  bool segment_complete = false;                                 // surfaced normally, ready for start_segment()
};

// The yo mission as a pure state machine: inputs in, set-points out.
// Dive from the surface to dive_to_m, climb to climb_to_m, repeat `yos`
// times; the last climb continues to the surface (one segment). Navigation
// starts the next segment from the surface. Any sensor, actuator or
// envelope violation latches the abort phase (full buoyancy, battery aft).
class YoMission {
 public:
  explicit YoMission(const YoMissionConfig& config) : config_(config) {}

  MissionOutputs update(const MissionInputs& in);

  Phase phase() const { return phase_; }

  // From the surface after a segment (or before the first with
  // start_at_launch false): dive again. Ignored in any other state.
  void start_segment() { start_requested_ = true; }

 private:
  void enter(Phase phase, MissionOutputs& out);
  AbortCause check_envelope(const MissionInputs& in) const;

  YoMissionConfig config_;
  Phase phase_ = Phase::kSurface;
  AbortCause abort_cause_ = AbortCause::kNone;
  bool started_ = false;
  bool final_climb_ = false;
  bool complete_ = false;
  hal::Micros start_us_ = 0;
  std::int32_t yos_completed_ = 0;
  std::int32_t segment_yos_ = 0;
  bool start_requested_ = false;
};

}  // namespace glider::fw
