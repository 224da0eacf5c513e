// SPDX-License-Identifier: Apache-2.0
#pragma once
// The mission above the yo: segments, GPS at the surface, dead reckoning
// under water, the depth-averaged current from each surfacing's DR error,
// the heading to the active waypoint corrected for that current, waypoints
// reached, and the end of the list. Pure logic on checked inputs.
#include <cmath>
#include <cstdint>

#include "glider/firmware/dead_reckoning.hpp"
#include "glider/firmware/mission_plan.hpp"
#include "glider/firmware/yo_mission.hpp"
#include "glider/hal/gps.hpp"

namespace glider::fw {

struct NavigatorInputs {
  hal::Micros now_us = 0;
  Phase phase = Phase::kSurface;
  bool segment_complete = false;  // the yo is at the surface, ready for the next segment
  bool attitude_ok = false;
  double pitch_rad = 0.0;
  double heading_rad = 0.0;
  bool depth_rate_ok = false;
  double depth_rate_m_s = 0.0;
  hal::GpsFix fix{};  // as read; checked here
  // The comms task (surface dialog): hold the vehicle up while it calls, or
  // resume at once (the pilot's Control-R) without the keystroke wait.
  bool hold_at_surface = false;
  bool resume_now = false;
};

// What one surfacing's fix said about the dead reckoning.
struct SurfacingReport {
  bool valid = false;
  double dr_error_m = 0.0;                // |fix - DR position|
  double distance_through_water_m = 0.0;  // the segment's DR distance
  double under_water_s = 0.0;
};

struct NavigatorOutputs {
  double heading_target_rad = 0.0;  // NaN: no heading control (fin centred)
  bool start_segment = false;
  bool surface_requested = false;
  bool mission_complete = false;
  AbortCause abort = AbortCause::kNone;
  bool new_fix = false;         // a fresh, checked fix this cycle (logged)
  SurfacingReport surfacing{};  // valid on the cycle of the first fix after a segment
};

class Navigator {
 public:
  Navigator(const MissionPlan& plan, const DeadReckoningConfig& dr, double max_wpt_distance_m);

  NavigatorOutputs update(const NavigatorInputs& in);

  // For the log.
  bool have_position() const { return have_origin_; }
  LatLon dr_position() const { return frame_.to_global(dr_.position()); }
  EastNorth current_m_s() const { return current_; }
  bool have_current() const { return have_current_; }
  std::int32_t active_waypoint() const { return waypoint_; }
  std::int32_t waypoints_reached() const { return reached_; }
  std::int32_t segments() const { return segments_; }
  double speed_m_s() const { return dr_.last_speed_m_s(); }  // horizontal, through the water
  // The mean of that speed over all the time spent gliding since launch
  // (Slocum's m_avg_speed; NaN before the first glide): the speed the
  // current correction counts the time to the waypoint at.
  double average_speed_m_s() const;
  // Up between segments (or before the first), and since when.
  bool at_surface() const { return state_ != State::kUnderWater; }
  hal::Micros surfaced_us() const { return surfaced_us_; }
  hal::Micros dive_us() const { return dive_us_; }
  // The comms task had a call connected (start_when 12: "no comms for
  // when_secs" counts from the last such time; before any, from launch).
  // Without a comms task (no modem: SIL's plain flights) each surfacing stands for comms.
  void note_comms(hal::Micros now_us) {
    last_comms_us_ = now_us;
    comms_reported_ = true;
  }
  // Why the last segment ended by time: 9 (every when_secs, from the previous
  // firing), 12 (no comms for when_secs), 0 (not by time).
  int surfaced_by_start_when() const { return surfaced_by_start_when_; }
  // A re-read mission (Control-F, validated): fly its waypoints from the first.
  void replace_plan(const MissionPlan& plan);
  // The depth-averaged current estimate carried over from before a start
  // (a forecast resumes a mission mid-flight with the glider's m_water_vx/vy).
  void seed_current(EastNorth current) {
    current_ = current;
    have_current_ = true;
  }
  // The mean glide speed carried over the same way (Slocum's m_avg_speed at
  // the dive, as if glided for `glided_s`): a resumed flight steers with
  // Slocum's current correction from its first moment, not the plain bearing
  // until its first glide. Ignored unless 0 < speed <= kMaxSeededSpeedMps and
  // 0 < glided_s < 1e9 (both finite); returns whether it was taken.
  static constexpr double kMaxSeededSpeedMps = 3.0;
  bool seed_average_speed(double speed_m_s, double glided_s) {
    if (!(std::isfinite(speed_m_s) && speed_m_s > 0.0 && speed_m_s <= kMaxSeededSpeedMps)) return false;
    if (!(std::isfinite(glided_s) && glided_s > 0.0 && glided_s < 1e9)) return false;
    glided_m_ = speed_m_s * glided_s;
    glided_s_ = glided_s;
    return true;
  }
  // The when_secs clocks carried over the same way: the start_when 9 clock
  // last started `since_surfacing_s` (its firing before the last surfacing,
  // else the arrival) and the last call connected `since_comms_s` before this
  // start (a forecast starts at the dive, after the glider's time at the
  // surface). Applied at launch; negative or non-finite values are ignored
  // (the launch counts).
  void seed_clocks(double since_surfacing_s, double since_comms_s) {
    seeded_since_surfacing_us_ = clock_age_us(since_surfacing_s);
    seeded_since_comms_us_ = clock_age_us(since_comms_s);
  }

 private:
  enum class State { kSurface, kUnderWater, kDone };

  static hal::Micros clock_age_us(double seconds) {
    return std::isfinite(seconds) && seconds > 0.0 && seconds < 1e9 ? static_cast<hal::Micros>(seconds * 1e6) : 0;
  }
  bool fix_is_fresh(const hal::GpsFix& fix, hal::Micros since_us) const;
  void on_fix(const hal::GpsFix& fix, NavigatorOutputs& out);
  void advance_waypoint();
  bool list_done() const;
  double heading_to_waypoint() const;

  MissionPlan plan_;
  double max_wpt_distance_m_;
  DeadReckoning dr_;
  LocalFrame frame_;
  bool have_origin_ = false;
  State state_ = State::kSurface;
  bool launched_ = false;
  hal::Micros surfaced_us_ = 0;
  hal::Micros dive_us_ = 0;
  hal::Micros last_us_ = 0;
  // when_secs clocks (Slocum's surface behaviour): start_when 9 counts from its
  // own previous firing (periodic; after another surfacing from the arrival,
  // launch first), start_when 12 from the last call connected (launch first),
  // not from the dive.
  hal::Micros last_surfacing_us_ = 0;  // the start_when 9 clock's start (HAL time need not start at 0)
  hal::Micros last_comms_us_ = 0;
  hal::Micros seeded_since_surfacing_us_ = 0;  // seed_clocks: ages at launch
  hal::Micros seeded_since_comms_us_ = 0;
  bool comms_reported_ = false;  // a comms task has called note_comms
  int surfaced_by_start_when_ = 0;
  bool when_secs_fired_ = false;  // the start_when 9 clock fired this dive (cleared on arrival)
  bool fix_this_surfacing_ = false;
  bool dr_error_pending_ = false;
  EastNorth position_{};  // last known (fix or DR)
  EastNorth current_{};
  bool have_current_ = false;
  double glided_m_ = 0.0;  // through the water, while the DR infers a speed
  double glided_s_ = 0.0;
  std::int32_t waypoint_ = 0;
  std::int32_t reached_ = 0;
  std::int32_t segments_ = 0;
};

}  // namespace glider::fw
