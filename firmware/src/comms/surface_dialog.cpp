// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/comms/surface_dialog.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "glider/utc_time.hpp"

namespace glider::fw::comms {
namespace {

// What a real glider prints for a position or a sensor it has never had.
constexpr const char* kNeverAge = "1e+308";
constexpr const char* kNoPosition = "69696969.000 N 69696969.000 E";
// "name(unit)=value" left, age right: the sensor lines are this wide.
constexpr int kSensorLineWidth = 47;

void print_position(const char* label, const DialogPosition& p, DialogQueue& out) {
  if (!p.valid) {
    out.appendf("%s %s measured %10s secs ago\r\n", label, kNoPosition, kNeverAge);
    return;
  }
  out.appendf("%s %9.3f N %10.3f E measured %10g secs ago\r\n", label, p.lat_nmea, p.lon_nmea, p.age_s);
}

void print_sensor(const DialogSensor& s, DialogQueue& out) {
  char left[96];
  int n = s.valid ? std::snprintf(left, sizeof left, "%s(%s)=%.15g", s.name, s.unit, s.value)
                  : std::snprintf(left, sizeof left, "%s(%s)=nan", s.name, s.unit);
  if (n < 0) return;
  if (n >= static_cast<int>(sizeof left)) n = sizeof left - 1;
  char age[32];
  if (s.valid) {
    std::snprintf(age, sizeof age, "%g", s.age_s);
  } else {
    std::snprintf(age, sizeof age, "%s", kNeverAge);
  }
  const int pad = kSensorLineWidth - n > static_cast<int>(std::strlen(age)) ? kSensorLineWidth - n
                                                                            : 1 + static_cast<int>(std::strlen(age));
  out.appendf("   sensor:%s%*s secs ago\r\n", left, pad, age);
}

// What the dialog prints for a time it cannot tell (not finite, or a year
// outside 0..9999): never a made-up date such as 1970.
constexpr const char* kUnknownTime = "unknown";

// UTC seconds -> whole seconds, truncated toward the earlier time (a clock
// never shows a second that has not begun). False when not finite or beyond
// year 9999 (the range check keeps the cast defined).
bool whole_seconds(double utc_s, std::int64_t& whole_s) {
  constexpr double kYear10000S = 253402300800.0;  // 10000-01-01T00:00:00Z
  if (!std::isfinite(utc_s) || utc_s < 0.0 || utc_s >= kYear10000S) return false;
  whole_s = static_cast<std::int64_t>(std::floor(utc_s));
  return true;
}

// "2026-11-27T05:40:12": the base library's ISO writer (one UTC code path),
// without its zone letter, as Slocum prints an abort's time.
void format_abort_time(double utc_s, char* out, std::size_t size) {
  const std::size_t n = utc::write_iso(out, size, utc_s);
  if (n == 0) {
    std::snprintf(out, size, "%s", kUnknownTime);
    return;
  }
  out[n - 1] = '\0';  // the 'Z'
}

}  // namespace

const char* slocum_abort_name(AbortCause cause) {
  switch (cause) {
    case AbortCause::kNone:
      return "none";
    case AbortCause::kOverdepth:
      return "MS_ABORT_OVERDEPTH";
    case AbortCause::kOvertime:
      return "MS_ABORT_OVERTIME";
    case AbortCause::kDepthSensor:
      return "MS_ABORT_NO_DEPTH_MEASUREMENT";
    case AbortCause::kAttitudeSensor:
      return "MS_ABORT_NO_HEADING_MEASUREMENT";
    case AbortCause::kActuatorFault:
      return "MS_ABORT_DEVICE_ERROR";
    case AbortCause::kLeak:
      return "MS_ABORT_LEAK";
    case AbortCause::kLowBattery:
      return "MS_ABORT_CHARGE_MIN";
    case AbortCause::kSameDepth:
      return "MS_ABORT_SAMEDEPTH";
    case AbortCause::kStalled:
      return "MS_ABORT_STALLED";
    case AbortCause::kWaypointTooFar:
      return "MS_ABORT_WPT_TOOFAR";
  }
  return "MS_ABORT_UNKNOWN";
}

void format_ctime(double utc_s, char* out, std::size_t size) {
  std::int64_t whole_s = 0;
  if (!whole_seconds(utc_s, whole_s) || utc::write_ctime(out, size, whole_s) == 0) {
    std::snprintf(out, size, "%s", kUnknownTime);
  }
}

void format_segment_name(char* out, std::size_t size, const char* vehicle, double utc_s, int mission, int segment) {
  std::int64_t whole_s = 0;
  if (!whole_seconds(utc_s, whole_s)) {
    std::snprintf(out, size, "%s-%s-%d-%d", vehicle, kUnknownTime, mission, segment);
    return;
  }
  const utc::Civil c = utc::civil_from_seconds(whole_s);
  const std::int64_t day_of_year = utc::days_from_civil(c.year, c.month, c.day) - utc::days_from_civil(c.year, 1, 1);
  std::snprintf(out, size, "%s-%04d-%03lld-%d-%d", vehicle, c.year, static_cast<long long>(day_of_year), mission,
                segment);
}

void print_vehicle_name(const char* name, DialogQueue& out) { out.appendf("Vehicle Name: %s\r\n", name); }

void print_dialog(const DialogSnapshot& s, DialogQueue& out) {
  out.appendf("\r\nGlider %s at surface.\r\n", s.vehicle_name);
  out.appendf("Because:%s [behavior %s start_when = %.1f]\r\n", s.because, s.behavior, s.start_when);
  out.appendf("MissionName:%s MissionNum:%s (%04d.%04d)\r\n", s.mission_name, s.segment_name, s.mission_number,
              s.segment_number);
  print_vehicle_name(s.vehicle_name, out);
  char when[40];
  format_ctime(s.utc_s, when, sizeof when);
  out.appendf("Curr Time: %s MT: %7.0f\r\n", when, std::floor(s.mission_time_s));
  print_position("DR  Location:", s.dr, out);
  out.appendf("GPS TooFar:   %s measured %10s secs ago\r\n", kNoPosition, kNeverAge);
  print_position("GPS Invalid :", s.gps_invalid, out);
  print_position("GPS Location:", s.gps, out);
  for (const DialogSensor& sensor : s.sensors) print_sensor(sensor, out);
  const DialogDevices& d = s.devices;
  out.appendf("devices:(t/m/s) errs: %4u/%3u/%3u warn: %4u/%3u/%3u odd: %4u/%3u/%3u\r\n", d.errors[0], d.errors[1],
              d.errors[2], d.warnings[0], d.warnings[1], d.warnings[2], d.oddities[0], d.oddities[1], d.oddities[2]);
  out.appendf("ABORT HISTORY: total since reset: %u\r\n", s.aborts.total);
  if (s.aborts.total > 0) {
    char when_iso[64];
    format_abort_time(s.aborts.last_time_utc_s, when_iso, sizeof when_iso);
    out.appendf("ABORT HISTORY: last abort cause: %s\r\n", slocum_abort_name(s.aborts.last_cause));
    out.appendf("ABORT HISTORY: last abort details: %s\r\n", to_string(s.aborts.last_cause));
    out.appendf("ABORT HISTORY: last abort time: %s\r\n", when_iso);
    out.appendf("ABORT HISTORY: last abort segment: %s\r\n", s.aborts.last_segment);
    out.appendf("ABORT HISTORY: last abort mission: %s\r\n", s.aborts.last_mission);
  }
  if (s.refusal[0] != '\0') out.appendf("%s refused: %s\r\n", s.refusal_by, s.refusal);
  out.appendf("Hit Control-R to RESUME the mission, or wait %.0f secs\r\n", s.keystroke_wait_s);
  out.append("Hit Control-C to END the mission\r\n");
  out.append("Hit Control-F to re-read mafiles\r\n");
  out.append("Hit Control-W for a device report\r\n");
}

}  // namespace glider::fw::comms
