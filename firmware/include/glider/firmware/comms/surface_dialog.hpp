// SPDX-License-Identifier: Apache-2.0
#pragma once
// The surface dialog: the block of text a Slocum prints at each surfacing
// and re-prints every printout_cycle_time, in the exact line formats the
// shore tools key on (docs/comms.md, Dialog, with the sources). Pure
// formatting of a snapshot into the output queue: no state, no allocation.
#include <cstdint>
#include <span>

#include "glider/firmware/comms/output_queue.hpp"
#include "glider/firmware/yo_mission.hpp"

namespace glider::fw::comms {

using DialogQueue = OutputQueue<8192>;

struct DialogPosition {
  bool valid = false;
  double lat_nmea = 0.0;  // ddmm.mmm, signed (south negative)
  double lon_nmea = 0.0;  // dddmm.mmm, signed (west negative)
  double age_s = 0.0;
};

struct DialogSensor {
  const char* name = "";
  const char* unit = "";
  bool valid = false;  // never seen: value NaN, age 1e+308 as on a real glider
  double value = 0.0;
  double age_s = 0.0;
};

struct DialogDevices {  // (t/m/s): total, this mission, this segment
  std::uint32_t errors[3] = {0, 0, 0};
  std::uint32_t warnings[3] = {0, 0, 0};
  std::uint32_t oddities[3] = {0, 0, 0};
};

struct DialogAborts {
  std::uint32_t total = 0;
  AbortCause last_cause = AbortCause::kNone;
  double last_time_utc_s = 0.0;
  const char* last_segment = "";
  const char* last_mission = "";
};

struct DialogSnapshot {
  const char* vehicle_name = "";
  const char* because = "";  // e.g. "Every when secs"
  const char* behavior = "surface";
  double start_when = 0.0;
  const char* mission_name = "";  // MISSION.MI
  const char* segment_name = "";  // <name>-<yyyy>-<ddd>-<mission>-<segment>
  std::int32_t mission_number = 0;
  std::int32_t segment_number = 0;
  double utc_s = 0.0;           // seconds since 1970 (Curr Time)
  double mission_time_s = 0.0;  // MT
  DialogPosition dr, gps, gps_invalid;
  std::span<const DialogSensor> sensors;
  DialogDevices devices;
  DialogAborts aborts;
  const char* refusal = "";              // a re-read mission refused since the last dialog ("" none)
  const char* refusal_by = "Control-F";  // what asked for it: Control-F, or an upload (zr)
  double keystroke_wait_s = 0.0;
};

// Slocum's name of an abort cause (MS_ABORT_...).
const char* slocum_abort_name(AbortCause cause);

// "Sat Mar 28 20:40:38 2026" (C's ctime, without its newline), UTC.
// "unknown" when utc_s is not finite or its year is outside 0..9999.
void format_ctime(double utc_s, char* out, std::size_t size);

// Slocum's segment name "<vehicle>-<yyyy>-<ddd>-<mission>-<segment>", ddd the
// UTC day of the year counted from 0 (as tm_yday). "<vehicle>-unknown-..."
// when utc_s cannot be told (as format_ctime).
void format_segment_name(char* out, std::size_t size, const char* vehicle, double utc_s, int mission, int segment);

// The whole dialog block, from "Glider <name> at surface." to the prompt.
void print_dialog(const DialogSnapshot& s, DialogQueue& out);
// Just "Vehicle Name: <name>" (whoru).
void print_vehicle_name(const char* name, DialogQueue& out);

}  // namespace glider::fw::comms
