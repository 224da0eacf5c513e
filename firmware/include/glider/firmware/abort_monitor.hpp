// SPDX-License-Identifier: Apache-2.0
#pragma once
// The abend checks beyond the yo's own envelope (overdepth, overtime and
// sensor/actuator validity live in YoMission): leak, low battery, stuck at
// the same depth, stalled. Pure logic on checked inputs; nothing allocates.
#include "glider/firmware/mission_plan.hpp"
#include "glider/firmware/yo_mission.hpp"
#include "glider/hal/time.hpp"

namespace glider::fw {

struct AbortMonitorInputs {
  hal::Micros now_us = 0;
  Phase phase = Phase::kSurface;
  bool depth_ok = false;
  double depth_m = 0.0;
  bool depth_rate_ok = false;
  double depth_rate_m_s = 0.0;  // + descending
  bool gliding = false;         // in a dive or climb with the pump where it was sent
  bool leak_ok = false;
  bool leak = false;
  bool power_ok = false;
  double charge_used_amphr = 0.0;
};

class AbortMonitor {
 public:
  explicit AbortMonitor(const AbortLimits& limits) : limits_(limits) {}

  AbortCause check(const AbortMonitorInputs& in);

  // Remaining charge in % of the capacity (100 before the first valid reading).
  double remaining_charge_pct() const { return remaining_pct_; }

 private:
  AbortCause check_samedepth(const AbortMonitorInputs& in);
  AbortCause check_stalled(const AbortMonitorInputs& in);

  AbortLimits limits_;
  double remaining_pct_ = 100.0;
  bool have_reference_ = false;
  double reference_depth_m_ = 0.0;
  hal::Micros reference_us_ = 0;
  bool stalling_ = false;
  hal::Micros stall_start_us_ = 0;
};

}  // namespace glider::fw
