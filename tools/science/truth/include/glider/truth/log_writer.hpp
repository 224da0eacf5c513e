// SPDX-License-Identifier: Apache-2.0
#pragma once
// A truth flight as the project's flight-log CSV (docs/flight-log.md: the
// Slocum names, units and signs; empty = no value this cycle; shortest
// round-trip numbers; a trailer), thinned like a real Slocum dbd log:
// about 2 % of cycles missing, a commanded value written only in the cycle
// that changed it (c_ballast_pumped, c_battpos, c_pitch; the autopilot's
// c_heading and c_fin are set every cycle), the CTD missing in ~5 % of rows.
// Truths (the water's velocity, the speed, ...) are not in the log: they
// go to the truth JSON, so the diagnosis sees only what a glider logs.
#include <cstdint>
#include <string>

#include "glider/truth/flight.hpp"

namespace glider::truth {

struct LogSettings {
  std::string vehicle_file;  // named in the metadata
  std::uint64_t seed = 1;    // the thinning's
  // A DVL's speed through water (sci_speed_through_water) when >= 0: the
  // true speed plus white noise of this sigma (m/s), on dives deeper than
  // dvl_min_depth_m only, as gliderflight-adcp's processed DVL. Negative: no
  // such column (the default: the diagnosis scores it, never fits it).
  double dvl_noise_m_s = -1.0;
  double dvl_min_depth_m = 12.0;
};

std::string log_text(const FlightResult& flight, const LogSettings& settings);
void write_log(const std::string& path, const FlightResult& flight, const LogSettings& settings);

}  // namespace glider::truth
