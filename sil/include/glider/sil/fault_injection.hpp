// SPDX-License-Identifier: Apache-2.0
#pragma once
// Faults the SIL can inject into the simulated HAL, to exercise the
// firmware's abort paths. Tests set them directly (SimHal::faults()); the
// scenario runner and `glider-sil --fault NAME@TIMEs` switch them on at a
// simulated time (FaultSchedule).
#include <optional>
#include <string>
#include <vector>

namespace glider::sil {

struct FaultInjection {
  bool depth_invalid = false;  // the pressure sensor reports no valid reading
  bool depth_frozen = false;   // readings stop updating (stale time stamp)
  bool attitude_invalid = false;
  bool attitude_frozen = false;
  bool pump_fault = false;  // the pump driver reports a fault
  bool pump_stuck = false;  // the pump silently stops moving (no fault flag)
  bool battery_fault = false;
  bool fin_fault = false;
  bool leak = false;          // the leak detector asserts
  bool gps_dead = false;      // no fixes at all
  double extra_load_w = 0.0;  // a short or a stuck heater: drains the battery
};

// One scheduled fault: switched on at `at_s` of simulated time, stays on.
struct ScheduledFault {
  std::string name;
  double at_s = 0.0;
};

// The names `--fault` accepts, one line each with what they do.
const std::vector<std::pair<std::string, std::string>>& fault_names();

// "leak@1200s", "leak@1200", "depth_invalid@30m": nullopt (and `error` set)
// when the text is not a known fault at a time.
std::optional<ScheduledFault> parse_fault(const std::string& text, std::string& error);

// The latest a fault may be scheduled: the 60 days a .mi mission may run
// (a fault at inf or 1e308 h is a typo, never a fault that does not happen).
inline constexpr double kMaxFaultTimeS = 60.0 * 86400.0;

// "1200s", "1200", "30m", "2h": seconds; nullopt unless a number with an
// optional unit that comes to [0, kMaxFaultTimeS] s (NaN and inf refused;
// shared with glider-plant's --fault).
std::optional<double> parse_fault_time(std::string time);

// Switches a named fault on; false if the name is unknown.
bool apply_fault(const std::string& name, FaultInjection& faults);

}  // namespace glider::sil
