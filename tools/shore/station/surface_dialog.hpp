// SPDX-License-Identifier: Apache-2.0
#pragma once
// The text a Slocum glider prints when it calls in (its surface dialog, and
// the answers to whoru), read line by line into what a pilot looks at: who,
// when, where, why it surfaced, its sensors and its aborts. The line formats
// are the real console's (docs/comms.md, "Shore station"; the test dialog in
// tests/shore/data notes where each format was observed).
#include <optional>
#include <string>
#include <vector>

namespace glider::shore {

// A position line: "GPS Location:  3310.021 N -11741.800 E measured  64.746 secs ago".
struct DialogFix {
  std::string kind;       // "gps", "gps_toofar", "gps_invalid" or "dr"
  double lat_ddmm = 0.0;  // as printed: [-]DDMM.MMM, negative south
  double lon_ddmm = 0.0;  // [-]DDDMM.MMM, negative west
  double lat_deg = 0.0;   // decimal degrees
  double lon_deg = 0.0;
  std::optional<double> age_s;  // none when the glider prints 1e+308 (never measured)
};

struct DialogSensor {
  std::string name;
  std::string unit;
  std::string value;            // as printed (a number, or text such as "nan")
  std::optional<double> age_s;  // none for 1e+308
};

struct DialogAborts {
  int total_since_reset = -1;
  std::string last_cause, last_details, last_time, last_segment, last_mission;
};

struct DialogDevices {
  int errors[3] = {0, 0, 0};  // total / this mission / this segment, as in "(t/m/s)"
  int warnings[3] = {0, 0, 0};
  int oddities[3] = {0, 0, 0};
};

// The latest value of every item seen in one call (the glider re-prints its
// dialog every printout_cycle_time: a later print replaces an earlier one).
struct SurfaceReport {
  std::string vehicle_name;
  std::string curr_time_text;               // "Sat Mar 28 20:40:38 2026"
  std::optional<long long> curr_time_unix;  // the same in seconds since 1970 (UTC)
  std::optional<double> mission_time_s;     // MT:
  std::vector<std::string> reasons;         // the text after "Because:" of each surfacing trigger
  std::string mission_name, mission_number;
  std::optional<DialogFix> gps;         // the valid fix ("GPS Location:")
  std::vector<DialogFix> gps_rejected;  // GPS TooFar / GPS Invalid lines
  std::optional<DialogFix> dr;
  std::vector<DialogSensor> sensors;  // in first-seen order, latest value
  std::optional<DialogAborts> aborts;
  std::optional<DialogDevices> devices;
  std::string prompt;  // the last GliderDOS prompt seen, e.g. "GliderDos N -1 >"
  int lines = 0;
  int unparsed_lines = 0;  // lines that looked like an item but did not parse
};

// Feeds one console line (without its line end). Returns true if the line
// was understood as a dialog item.
bool parse_dialog_line(const std::string& line, SurfaceReport& report);

// A GliderDOS prompt ("GliderDos N -1 >", "GliderDOS A 8 >"), possibly with
// the echo of a typed command after it. Returns the prompt text or "".
std::string match_prompt(const std::string& text);

// [-]DDMM.MMM -> decimal degrees.
double ddmm_to_degrees(double ddmm);

// A glider name is used as a folder name: letters, digits, '_' and '-', 1-32 characters.
bool valid_glider_name(const std::string& name);

}  // namespace glider::shore
