// SPDX-License-Identifier: Apache-2.0
#pragma once
// The mission as the glider flies it now: its .mi and .ma files as the
// pilot keeps them in GLIDER/mission/ (missions/NAME.mi, mafiles/*.ma), the
// files the shore delivered since (to-glider/sent/), and any queued in
// to-glider/ (or a file being rehearsed). Every change goes through the
// firmware's own mission loader (prepare_mission) on a staged copy, exactly
// as the glider's MissionFileReloader::install does: a file the firmware
// would refuse is refused with its message, and an accepted change replaces
// the plan (waypoints and surfacing) and restarts the waypoint list.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glider/firmware/app/mission_setup.hpp"
#include "glider/forecast/surfacing_history.hpp"

namespace glider::forecast {

struct MissionNow {
  fw::FlightSoftwareConfig config;  // as launched, with the plan of the last accepted change
  std::filesystem::path mission_file;
  std::vector<std::string> applied;  // files applied on top of the launch mission, in order
  std::int32_t active_waypoint = 0;  // index into config.plan.waypoints
  std::int32_t waypoints_reached = 0;
  std::size_t replay_from = 0;  // the first event flown under the current plan
  std::string refusal;          // non-empty: the firmware refuses the file named in it
  std::vector<std::string> notes;
};

// The .mi of a glider folder: `explicit_mission` if given, else the one in
// GLIDER/mission/ (missions/NAME.mi named by the last event, or the only .mi).
// Throws std::runtime_error when there is none or several to choose from.
std::filesystem::path find_mission(const std::filesystem::path& glider_dir, const std::string& explicit_mission,
                                   const std::string& named);

// Launch config, delivered and queued changes (and `extra`, rehearsed), and
// the waypoint the glider flies to now (replayed from the fixes since the
// last change: a fix within the radius, or a straight track between two
// fixes passing within it, counts the waypoint reached).
MissionNow mission_now(const std::filesystem::path& glider_dir, const std::filesystem::path& mission_file,
                       const fw::app::VehicleSetup& setup, const std::vector<Surfacing>& history,
                       const std::vector<std::filesystem::path>& extra, bool include_queue);

// The plan the next dive flies: the waypoint list rotated so the active one
// comes first, legs reduced by those already reached.
fw::MissionPlan remaining_plan(const MissionNow& now);

}  // namespace glider::forecast
