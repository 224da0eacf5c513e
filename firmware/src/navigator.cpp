// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/navigator.hpp"

#include "glider/firmware/current_correction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glider::fw {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Fixes older than this when read are not news (the receiver keeps its last).
constexpr double kFixMaxAgeS = 5.0;
// A segment this short says nothing useful about the current: the DR's own
// error over a yo or two (inflections, speed) would dominate the estimate.
constexpr double kMinSegmentForCurrentS = 600.0;

bool plausible(const hal::GpsFix& f) {
  return f.valid && f.quality > 0 && std::isfinite(f.latitude_deg) && std::isfinite(f.longitude_deg) &&
         std::fabs(f.latitude_deg) <= 90.0 && std::fabs(f.longitude_deg) <= 180.0;
}

}  // namespace

Navigator::Navigator(const MissionPlan& plan, const DeadReckoningConfig& dr, double max_wpt_distance_m)
    : plan_(plan), max_wpt_distance_m_(max_wpt_distance_m), dr_(dr) {}

bool Navigator::fix_is_fresh(const hal::GpsFix& fix, hal::Micros since_us) const {
  return plausible(fix) && fix.time_us >= since_us && hal::to_seconds(last_us_ - fix.time_us) <= kFixMaxAgeS;
}

bool Navigator::list_done() const {
  if (plan_.waypoint_count == 0) return segments_ >= 1;  // a yo-only mission is one segment
  if (plan_.legs_to_run == kLegsLoopForever) return false;
  const std::int32_t legs = plan_.legs_to_run == kLegsOnce ? plan_.waypoint_count : plan_.legs_to_run;
  return reached_ >= legs;
}

void Navigator::advance_waypoint() {
  ++reached_;
  waypoint_ = (waypoint_ + 1) % plan_.waypoint_count;
}

double Navigator::average_speed_m_s() const {
  return glided_s_ > 0.0 ? glided_m_ / glided_s_ : std::numeric_limits<double>::quiet_NaN();
}

double Navigator::heading_to_waypoint() const {
  const EastNorth target = frame_.to_local(plan_.waypoints[static_cast<std::size_t>(waypoint_)]);
  const EastNorth from = dr_.position();
  const double bearing = bearing_rad(from, target);
  if (!plan_.current_correction || !have_current_) return bearing;
  // Slocum's law (current_correction.hpp) with the running mean of the DR's
  // speed through the water, as Slocum uses m_avg_speed: the instantaneous
  // speed drops to zero at every inflection and would swing the aim point
  // (with m_speed the law is 7 deg median, 27 deg p90 off comet-2019's
  // c_heading; with m_avg_speed 0.01 / 0.03 deg).
  const double heading = aim_point_heading(from, target, current_, average_speed_m_s());
  return std::isfinite(heading) ? heading : bearing;
}

void Navigator::on_fix(const hal::GpsFix& fix, NavigatorOutputs& out) {
  const LatLon here{fix.latitude_deg, fix.longitude_deg};
  if (!have_origin_) {
    frame_ = LocalFrame(here);
    have_origin_ = true;
  }
  const EastNorth position = frame_.to_local(here);
  if (dr_error_pending_) {
    dr_error_pending_ = false;
    const double under_water_s = hal::to_seconds(surfaced_us_ - dive_us_);
    const EastNorth error{position.east_m - dr_.position().east_m, position.north_m - dr_.position().north_m};
    out.surfacing = {true, std::hypot(error.east_m, error.north_m), dr_.distance_through_water_m(), under_water_s};
    // The DR already carried the previous estimate: what is left over is
    // the correction to it (Slocum's m_water_vx/vy update).
    if (under_water_s >= kMinSegmentForCurrentS) {
      current_.east_m += error.east_m / under_water_s;
      current_.north_m += error.north_m / under_water_s;
      have_current_ = true;
    }
  }
  position_ = position;
  dr_.reset(position);
  out.new_fix = true;
  if (plan_.waypoint_count > 0) {
    const EastNorth target = frame_.to_local(plan_.waypoints[static_cast<std::size_t>(waypoint_)]);
    const double distance = distance_m(position, target);
    if (distance <= plan_.waypoint_radius_m && !list_done()) advance_waypoint();
    if (max_wpt_distance_m_ > 0.0 && distance > max_wpt_distance_m_) out.abort = AbortCause::kWaypointTooFar;
  }
}

void Navigator::replace_plan(const MissionPlan& plan) {
  plan_ = plan;
  waypoint_ = 0;
  reached_ = 0;
  if (state_ == State::kDone) state_ = State::kSurface;
}

NavigatorOutputs Navigator::update(const NavigatorInputs& in) {
  NavigatorOutputs out;
  out.heading_target_rad = kNaN;
  const double dt_s = launched_ ? hal::to_seconds(in.now_us - last_us_) : 0.0;
  last_us_ = in.now_us;
  if (!launched_) {
    // Launch: the first surfacing and the start of comms, unless a resumed
    // flight carried its clocks over (seed_clocks).
    last_surfacing_us_ = in.now_us - seeded_since_surfacing_us_;
    last_comms_us_ = in.now_us - seeded_since_comms_us_;
  }
  launched_ = true;

  // A yo-only mission dives at launch by itself (YoMission start_at_launch).
  if (state_ == State::kSurface && (in.phase == Phase::kDive || in.phase == Phase::kClimb)) {
    state_ = State::kUnderWater;
    dive_us_ = in.now_us;
    surfaced_by_start_when_ = 0;
    dr_.reset(position_);
    ++segments_;
  }

  if (state_ == State::kUnderWater) {
    if (in.segment_complete || in.phase == Phase::kSurface) {
      state_ = State::kSurface;
      surfaced_us_ = in.now_us;
      // A surfacing by the when_secs clock restarted that clock when it
      // fired (below); any other restarts it at the arrival.
      if (!when_secs_fired_) last_surfacing_us_ = in.now_us;
      when_secs_fired_ = false;
      if (!comms_reported_) last_comms_us_ = in.now_us;
      fix_this_surfacing_ = false;
      dr_error_pending_ = have_origin_;
    } else {
      if (in.phase != Phase::kAbort && in.attitude_ok && in.depth_rate_ok && dt_s > 0.0) {
        dr_.update(in.pitch_rad, in.heading_rad, in.depth_rate_m_s, current_, dt_s);
        // The average speed counts gliding only (Slocum's m_avg_speed
        // stays at the glide speed through surfacings and inflections).
        if (dr_.last_speed_m_s() > 0.0) {
          glided_m_ += dr_.last_speed_m_s() * dt_s;
          glided_s_ += dt_s;
        }
      }
      if (plan_.waypoint_count > 0 && have_origin_) {
        const EastNorth target = frame_.to_local(plan_.waypoints[static_cast<std::size_t>(waypoint_)]);
        if (distance_m(dr_.position(), target) <= plan_.waypoint_radius_m && !list_done()) advance_waypoint();
        if (list_done()) out.surface_requested = true;
        out.heading_target_rad = heading_to_waypoint();
      } else if (std::isfinite(plan_.heading_rad)) {
        out.heading_target_rad = plan_.heading_rad;
      }
      if (when_secs_fired_) {
        out.surface_requested = true;  // fired this dive: climbing to the surface
      } else if (plan_.surface_interval_s > 0.0 &&
                 hal::to_seconds(in.now_us - last_surfacing_us_) >= plan_.surface_interval_s) {
        // Slocum's start_when 9 is periodic: the next when_secs counts from
        // this firing (the surface behaviour's activation), not from the
        // arrival a climb later. comet-2019's x_surface_active went to 4 at
        // 1566405473.1 (dive 154, at 17.6 m) and 1566416282.1 (dive 156, at
        // 4.0 m): 10809 s apart for when_secs 10800 (a 4.5 s log cycle),
        // while the arrivals at 1 m were 10700 s apart (docs/comms.md).
        out.surface_requested = true;
        surfaced_by_start_when_ = 9;
        when_secs_fired_ = true;
        last_surfacing_us_ = in.now_us;
      } else if (plan_.no_comms_interval_s > 0.0 &&
                 hal::to_seconds(in.now_us - last_comms_us_) >= plan_.no_comms_interval_s) {
        out.surface_requested = true;
        surfaced_by_start_when_ = 12;
      }
      return out;
    }
  }
  if (state_ == State::kDone) {
    out.mission_complete = true;
    return out;
  }

  // At the surface (launch or between segments).
  if (!in.segment_complete) return out;  // still finishing the climb, or aborting
  if (fix_is_fresh(in.fix, surfaced_us_)) {
    fix_this_surfacing_ = true;
    on_fix(in.fix, out);
  }
  const double at_surface_s = hal::to_seconds(in.now_us - surfaced_us_);
  const bool dwelt = at_surface_s >= plan_.surface_dwell_s || in.resume_now;
  const bool gave_up = at_surface_s >= std::max(plan_.gps_wait_s, plan_.surface_dwell_s);
  if (in.hold_at_surface || !((fix_this_surfacing_ && dwelt) || gave_up)) return out;
  if (list_done()) {
    state_ = State::kDone;
    out.mission_complete = true;
    return out;
  }
  // Without any fix ever, waypoints cannot be flown: stay up and keep
  // listening (safe, and visible) rather than dive blind.
  if (plan_.waypoint_count > 0 && !have_origin_) return out;
  dr_error_pending_ = false;
  dr_.reset(position_);
  dive_us_ = in.now_us;
  state_ = State::kUnderWater;
  surfaced_by_start_when_ = 0;  // this segment's end is not said yet
  ++segments_;
  out.start_segment = true;
  return out;
}

}  // namespace glider::fw
