// SPDX-License-Identifier: Apache-2.0
// A Slocum argument file (.ma) from memory on arbitrary text: the first byte
// picks the behavior that includes it, the rest is the file; then the
// mission loader on what was read (its range checks of every argument and
// waypoint). Errors are diagnostics, never a crash, never undefined behaviour.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "glider/firmware/mission_file/mi_document.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace mf = glider::fw::mission_file;
  if (size == 0) return 0;
  constexpr std::array<const char*, 5> kBehaviors{"goto_list", "yo", "surface", "sample", "prepare_to_dive"};
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  const mf::MiDocument doc = mf::parse_ma_text(text, "fuzz.ma", kBehaviors[data[0] % kBehaviors.size()]);
  const mf::LoadedMission loaded = mf::load_mission(doc, mf::MissionVehicle{}, glider::fw::FlightSoftwareConfig{});
  for (const mf::Diagnostic& d : loaded.diagnostics) (void)d.text();
  return 0;
}
