// SPDX-License-Identifier: Apache-2.0
#pragma once
// Faults of the plant, switched on at a time after launch (the firmware's
// first actuator command) and left on: what the hardware does, seen by the
// firmware only through its interfaces.
#include <optional>
#include <string>
#include <vector>

namespace glider::plant {

enum class PlantFaultKind {
  kPumpStall,      // the pump mechanism jams; its drive latches a Stall fault
  kSlideStall,     // the same for the battery slide
  kRudderStall,    // and for the rudder
  kDepthSilent,    // the depth transmitter stops answering
  kCompassSilent,  // the compass stops sending
  kGpsSilent,      // the GPS receiver stops sending
  kPlantSilent,    // everything: no Modbus answer, no sentence (power lost)
};

struct PlantFault {
  PlantFaultKind kind;
  std::string name;
  double at_s = 0.0;  // simulated seconds after launch
};

struct PlantFaultName {
  std::string name;
  std::string what;
  std::string sil;  // glider-sil's --fault that the firmware should see alike
};
const std::vector<PlantFaultName>& plant_fault_names();

// "pump_stall@120s", "depth_silent@2m", "plant_silent@300": nullopt (and
// `error` set) when the text is not a plant fault at a time.
std::optional<PlantFault> parse_plant_fault(const std::string& text, std::string& error);

}  // namespace glider::plant
