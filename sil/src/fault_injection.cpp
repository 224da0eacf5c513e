// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/fault_injection.hpp"

#include <cstdlib>

namespace glider::sil {

const std::vector<std::pair<std::string, std::string>>& fault_names() {
  static const std::vector<std::pair<std::string, std::string>> names{
      {"depth_invalid", "pressure sensor reports invalid readings"},
      {"depth_frozen", "pressure readings stop updating (stale)"},
      {"attitude_invalid", "attitude sensor reports invalid readings"},
      {"attitude_frozen", "attitude readings stop updating (stale)"},
      {"pump_fault", "buoyancy pump driver reports a fault"},
      {"pump_stuck", "buoyancy pump stops moving without reporting it"},
      {"battery_fault", "battery slide driver reports a fault"},
      {"fin_fault", "fin (rudder) driver reports a fault"},
      {"leak", "leak detector asserts"},
      {"gps_dead", "GPS gives no fixes"},
      {"power_drain", "an extra 200 W load drains the main battery"},
  };
  return names;
}

bool apply_fault(const std::string& name, FaultInjection& f) {
  if (name == "depth_invalid")
    f.depth_invalid = true;
  else if (name == "depth_frozen")
    f.depth_frozen = true;
  else if (name == "attitude_invalid")
    f.attitude_invalid = true;
  else if (name == "attitude_frozen")
    f.attitude_frozen = true;
  else if (name == "pump_fault")
    f.pump_fault = true;
  else if (name == "pump_stuck")
    f.pump_stuck = true;
  else if (name == "battery_fault")
    f.battery_fault = true;
  else if (name == "fin_fault")
    f.fin_fault = true;
  else if (name == "leak")
    f.leak = true;
  else if (name == "gps_dead")
    f.gps_dead = true;
  else if (name == "power_drain")
    f.extra_load_w = 200.0;
  else
    return false;
  return true;
}

std::optional<double> parse_fault_time(std::string time) {
  double scale = 1.0;
  if (!time.empty() && (time.back() == 's' || time.back() == 'm' || time.back() == 'h')) {
    scale = time.back() == 'h' ? 3600.0 : time.back() == 'm' ? 60.0 : 1.0;
    time.pop_back();
  }
  char* end = nullptr;
  const double at_s = std::strtod(time.c_str(), &end);
  if (time.empty() || end != time.c_str() + time.size()) return std::nullopt;
  const double seconds = at_s * scale;
  if (!(seconds >= 0.0 && seconds <= kMaxFaultTimeS)) return std::nullopt;  // NaN and inf fail too
  return seconds;
}

std::optional<ScheduledFault> parse_fault(const std::string& text, std::string& error) {
  const auto at = text.find('@');
  const std::string name = text.substr(0, at);
  FaultInjection probe;
  if (!apply_fault(name, probe)) {
    error = "unknown fault '" + name + "' (known: ";
    for (const auto& [known, what] : fault_names()) error += known + " ";
    error.back() = ')';
    return std::nullopt;
  }
  double at_s = 0.0;
  if (at != std::string::npos) {
    const auto time = parse_fault_time(text.substr(at + 1));
    if (!time) {
      error = "fault time in '" + text + "' is not a number of s, m or h in [0, " +
              std::to_string(static_cast<long>(kMaxFaultTimeS)) + "] s";
      return std::nullopt;
    }
    at_s = *time;
  }
  return ScheduledFault{name, at_s};
}

}  // namespace glider::sil
