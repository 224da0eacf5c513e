// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/abort_monitor.hpp"

#include <cmath>

namespace glider::fw {

AbortCause AbortMonitor::check_samedepth(const AbortMonitorInputs& in) {
  const bool under_way = in.phase == Phase::kDive || in.phase == Phase::kClimb;
  if (!(limits_.samedepth_for_s > 0.0) || !under_way || !in.depth_ok) {
    have_reference_ = false;
    return AbortCause::kNone;
  }
  if (!have_reference_ || std::fabs(in.depth_m - reference_depth_m_) > limits_.samedepth_band_m) {
    have_reference_ = true;
    reference_depth_m_ = in.depth_m;
    reference_us_ = in.now_us;
    return AbortCause::kNone;
  }
  return hal::to_seconds(in.now_us - reference_us_) > limits_.samedepth_for_s ? AbortCause::kSameDepth
                                                                              : AbortCause::kNone;
}

AbortCause AbortMonitor::check_stalled(const AbortMonitorInputs& in) {
  if (!(limits_.stalled_for_s > 0.0) || !in.gliding || !in.depth_rate_ok) {
    stalling_ = false;
    return AbortCause::kNone;
  }
  // The depth rate in the commanded direction (+ = going the right way).
  const double along = in.phase == Phase::kDive ? in.depth_rate_m_s : -in.depth_rate_m_s;
  if (along >= limits_.stalled_depth_rate_m_s) {
    stalling_ = false;
    return AbortCause::kNone;
  }
  if (!stalling_) {
    stalling_ = true;
    stall_start_us_ = in.now_us;
  }
  return hal::to_seconds(in.now_us - stall_start_us_) > limits_.stalled_for_s ? AbortCause::kStalled
                                                                              : AbortCause::kNone;
}

AbortCause AbortMonitor::check(const AbortMonitorInputs& in) {
  if (in.leak_ok && in.leak) return AbortCause::kLeak;
  if (in.power_ok && std::isfinite(in.charge_used_amphr) && limits_.battery_capacity_amphr > 0.0) {
    remaining_pct_ = 100.0 * (1.0 - in.charge_used_amphr / limits_.battery_capacity_amphr);
    if (limits_.remaining_charge_min_pct > 0.0 && remaining_pct_ < limits_.remaining_charge_min_pct) {
      return AbortCause::kLowBattery;
    }
  }
  const AbortCause same = check_samedepth(in);
  if (same != AbortCause::kNone) return same;
  return check_stalled(in);
}

}  // namespace glider::fw
