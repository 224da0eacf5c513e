// SPDX-License-Identifier: Apache-2.0
#include "plant_faults.hpp"

#include <utility>

#include "glider/sil/fault_injection.hpp"

namespace glider::plant {
namespace {

const std::vector<std::pair<std::string, PlantFaultKind>>& kinds() {
  static const std::vector<std::pair<std::string, PlantFaultKind>> table{
      {"pump_stall", PlantFaultKind::kPumpStall},         {"slide_stall", PlantFaultKind::kSlideStall},
      {"rudder_stall", PlantFaultKind::kRudderStall},     {"depth_silent", PlantFaultKind::kDepthSilent},
      {"compass_silent", PlantFaultKind::kCompassSilent}, {"gps_silent", PlantFaultKind::kGpsSilent},
      {"plant_silent", PlantFaultKind::kPlantSilent}};
  return table;
}

}  // namespace

const std::vector<PlantFaultName>& plant_fault_names() {
  static const std::vector<PlantFaultName> names{
      {"pump_stall", "the pump jams; its drive latches a Stall fault when told to move", "pump_fault"},
      {"slide_stall", "the battery slide jams; its drive latches a Stall fault when told to move", "battery_fault"},
      {"rudder_stall", "the rudder jams; its drive latches a Stall fault when told to move", "fin_fault"},
      {"depth_silent", "the depth transmitter stops answering", "depth_invalid"},
      {"compass_silent", "the compass stops sending", "attitude_frozen"},
      {"gps_silent", "the GPS receiver stops sending", "gps_dead"},
      {"plant_silent", "every device stops answering and sending (power lost)", "depth_invalid"},
  };
  return names;
}

std::optional<PlantFault> parse_plant_fault(const std::string& text, std::string& error) {
  const auto at = text.find('@');
  const std::string name = text.substr(0, at);
  if (name == "leak") {
    error =
        "leak: the target reads its leak detector on a GPIO line (libgpiod), which needs a kernel GPIO chip; "
        "the plant cannot drive one from user space (the gpio_kernel test covers the line, glider-sil the abort)";
    return std::nullopt;
  }
  std::optional<PlantFaultKind> kind;
  for (const auto& [known, k] : kinds()) {
    if (known == name) kind = k;
  }
  if (!kind) {
    error = "unknown plant fault '" + name + "' (known:";
    for (const auto& n : plant_fault_names()) error += " " + n.name;
    error += ")";
    return std::nullopt;
  }
  if (at == std::string::npos) return PlantFault{*kind, name, 0.0};
  const auto at_s = sil::parse_fault_time(text.substr(at + 1));
  if (!at_s) {
    error = "fault time in '" + text + "' is not a number of s, m or h in [0, " +
            std::to_string(static_cast<long>(sil::kMaxFaultTimeS)) + "] s";
    return std::nullopt;
  }
  return PlantFault{*kind, name, *at_s};
}

}  // namespace glider::plant
