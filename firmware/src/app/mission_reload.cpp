// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/mission_reload.hpp"

#include <cstdio>
#include <exception>

namespace glider::fw::app {

bool MissionFileReloader::reread(FlightSoftware& flight, char* refusal, std::size_t size) {
  std::string why;
  try {
    const PreparedMission prepared = prepare_mission(mission_, setup_, options_);
    if (prepared.config) {
      flight.replace_plan(prepared.config->plan);
      return true;
    }
    // The first error names file:line, key, value and range.
    for (const std::string& line : mission_messages(prepared, true)) {
      why = line;
      break;
    }
    if (why.empty()) why = prepared.refusal;
  } catch (const std::exception& e) {
    why = e.what();
  }
  std::snprintf(refusal, size, "%s", why.empty() ? "mission refused" : why.c_str());
  return false;
}

}  // namespace glider::fw::app
