// SPDX-License-Identifier: Apache-2.0
// The Slocum .mi reader and the mission loader on arbitrary text: errors are
// diagnostics, never a crash, never undefined behaviour. The argument files
// (args_from_file) are looked up next to the committed comet-nsb3 mission.
#include <cstddef>
#include <cstdint>
#include <string>

#include "glider/firmware/mission_file/mission_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace mf = glider::fw::mission_file;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const mf::MiDocument doc =
      mf::parse_mi_text(text, "fuzz.mi", GLIDER_SOURCE_DIR "/boards/missions/comet-nsb3/missions");
  const mf::LoadedMission loaded = mf::load_mission(doc, mf::MissionVehicle{}, glider::fw::FlightSoftwareConfig{});
  for (const mf::Diagnostic& d : loaded.diagnostics) (void)d.text();
  return 0;
}
