// SPDX-License-Identifier: Apache-2.0
#pragma once
// A glider's surfacings as the shore recorded them (logs/*.surfacing.json,
// schema glider-shore-surfacing/1, docs/comms.md): the fixes, the glider's
// own depth-averaged current estimate (m_water_vx/vy in its dialog) and the
// files it took. Read in time order; a malformed event is an error naming
// its file, an event without a fix is kept (the glider said nothing useful).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glider::forecast {

struct Surfacing {
  std::filesystem::path file;
  std::string glider;
  double call_start_utc_s = 0.0;                 // the glider is up (its fix is from then)
  double call_end_utc_s = 0.0;                   // it dives soon after
  double mission_time_s = -1.0;                  // MT: of its dialog (-1: not said)
  std::optional<double> lat_deg, lon_deg;        // GPS fix
  std::optional<double> dr_lat_deg, dr_lon_deg;  // the glider's dead-reckoned position on surfacing
  std::optional<double> water_vx_m_s, water_vy_m_s;
  std::string mission_name;
  std::vector<std::string> files_delivered;  // names sent to the glider in this call
  std::string reasons;                       // why it surfaced (Because: lines)
  bool surfaced_by_abort = false;            // a Because: line names an abort
  std::string last_abort_cause;              // ABORT HISTORY's last cause (and details), "" if none said
  bool has_fix() const { return lat_deg && lon_deg; }
};

// Reads every logs/*.surfacing.json of `glider_dir`, sorted by call start.
// Throws std::runtime_error naming the file for a malformed event, another
// schema, or an event of another glider than the first.
std::vector<Surfacing> read_surfacings(const std::filesystem::path& glider_dir);

// One event (exposed for tests and the benchmark's real-data replays).
Surfacing parse_surfacing(const std::filesystem::path& file);

// "YYYY-MM-DDTHH:MM:SSZ" <-> seconds since 1970 (UTC). Throws on a bad text.
double parse_utc(const std::string& text, const std::string& where);
std::string format_utc(double utc_s);

}  // namespace glider::forecast
