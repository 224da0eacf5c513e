// SPDX-License-Identifier: Apache-2.0
#pragma once
// UTC text <-> seconds since 1970-01-01T00:00:00Z (POSIX time: no leap
// seconds), checked. The one place where a UTC time is read or written, so a
// launch time, a NetCDF attribute, a call ID and a glider's dialog follow the
// same rules: a date that does not exist (30 February), a field out of range
// (24:00, second 60), a missing or extra character is refused, never
// normalised into another time the way timegm would. Parsing needs no heap
// and no exceptions (the firmware may use it); the civil calendar is
// proleptic Gregorian (H. Hinnant's days_from_civil algorithm).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace glider::utc {

// A calendar date and time of day, every field in its natural range.
struct Civil {
  int year = 1970;
  int month = 1;   // 1..12
  int day = 1;     // 1..days_in_month
  int hour = 0;    // 0..23
  int minute = 0;  // 0..59
  int second = 0;  // 0..59
};

bool is_leap_year(int year);
// 0 for a month outside 1..12.
int days_in_month(int year, int month);
// Days since 1970-01-01 of a date (not checked: pass a valid one).
std::int64_t days_from_civil(int year, int month, int day);
// Seconds since 1970 -> calendar fields.
Civil civil_from_seconds(std::int64_t seconds);
// 0 = Sunday ... 6 = Saturday.
int weekday(std::int64_t seconds);

// What a reader accepts beyond the form itself.
struct Rules {
  int min_year = 1970;
  int max_year = 9999;
  // Digits allowed after the seconds' '.' (0: whole seconds only). At most 9.
  int max_fraction_digits = 9;
};

// The result of a parse. On failure `problem` says what is wrong in a few
// words ("day 30 does not exist in that month" style, without the text: the
// caller names the text, the file and the key).
struct Parsed {
  bool ok = false;
  std::int64_t whole_s = 0;  // seconds since 1970, the fraction dropped
  double fraction_s = 0.0;   // [0, 1)
  const char* problem = "";
  double seconds() const { return static_cast<double>(whole_s) + fraction_s; }
};

// ISO 8601 extended form, the whole text: "2026-11-27T05:40:12Z" or with a
// fraction "2026-11-27T05:40:12.25Z".
Parsed parse_iso(std::string_view text, const Rules& rules = {});
// ISO 8601 basic form without zone, the whole text: "20261127T054012"
// (the shore's call IDs, the NetCDF file names).
Parsed parse_compact(std::string_view text, const Rules& rules = {});
// C's asctime form a Slocum glider prints ("Curr Time: Fri Nov 27 05:40:12
// 2026"), the whole text; the day may be padded with a space ("Nov  6") or
// not; the weekday must be the date's.
Parsed parse_ctime(std::string_view text, const Rules& rules = {});

// Seconds -> "2026-11-27T05:40:12Z", with `decimals` (0..6) digits of
// fraction: truncated toward the earlier time (a clock never shows a second
// that has not begun), after absorbing the double's own representation error
// (1764222012.3 shows .3, not .2999). Empty for non-finite seconds or a year
// outside 0..9999. Round first (std::round) for the nearest second.
std::string format_iso(double seconds, int decimals = 0);
// Seconds -> "20261127T054012" (same truncation, whole seconds).
std::string format_compact(double seconds);
// Seconds -> "Fri Nov 27 05:40:12 2026" (asctime's form, day space-padded).
std::string format_ctime(std::int64_t seconds);

// The same without the heap: writes the text and a terminating NUL into
// `out` and returns its length, 0 when it does not fit or cannot be
// written (same cases as above).
std::size_t write_iso(char* out, std::size_t size, double seconds, int decimals = 0);
std::size_t write_ctime(char* out, std::size_t size, std::int64_t seconds);

}  // namespace glider::utc
