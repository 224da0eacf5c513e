// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which sensors a Slocum file carries, and how often: the glider's
// sbdlist.dat / tbdlist.dat (docs/slocum-binary.md, "Writing"). A text file,
// one sensor per line, `#` starts a comment, blank lines ignored:
//
//   m_present_time
//   m_depth          10     # at most one value every 10 s
//
// The optional number is the sensor's decimation: seconds between stored
// values (0 or absent: every cycle it has a value). Read at start-up only
// (allocates); refusals name file:line, the sensor, the value and the range.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include "glider/firmware/log/slocum_sensors.hpp"

namespace glider::fw {

inline constexpr double kMaxSlocumDecimationS = 86400.0;

struct SlocumSelection {
  std::array<bool, kSlocumFlightSensorCount> logged{};
  std::array<double, kSlocumFlightSensorCount> interval_s{};  // 0: every cycle
  std::size_t count() const;
};

// Every sensor, every cycle (the .dbd).
SlocumSelection all_slocum_sensors();

struct SlocumListResult {
  SlocumSelection selection;
  std::string error;  // empty: accepted
};

// Parses the text of an sbdlist.dat; `file` names it in refusals.
// m_present_time is always stored (every written cycle needs its time):
// added when not listed, refused with a decimation.
SlocumListResult parse_slocum_list(std::string_view text, std::string_view file);
// Reads and parses the file at `path`.
SlocumListResult read_slocum_list(const std::string& path);

// The list used when none is given: what a pilot looks at on every surfacing.
inline constexpr std::string_view kDefaultSbdList =
    "# built-in sbdlist.dat (glider-sil / glider-firmware without --sbdlist)\n"
    "m_present_time\n"
    "m_depth 10\n"
    "m_pitch 30\n"
    "m_heading 30\n"
    "m_battpos 30\n"
    "m_ballast_pumped 30\n"
    "m_depth_state\n"
    "m_gps_lat\n"
    "m_gps_lon\n"
    "m_lat 60\n"
    "m_lon 60\n"
    "m_water_vx\n"
    "m_water_vy\n"
    "m_battery 300\n"
    "m_coulomb_amphr_total 300\n"
    "m_leakdetect\n"
    "x_abort_cause\n"
    "x_waypoint\n"
    "x_mission_complete\n";

}  // namespace glider::fw
