// SPDX-License-Identifier: Apache-2.0
// The dialog's times and the segment name go through the base library's
// checked UTC writer (glider/utc_time.hpp): the same text as C's gmtime for
// a good time, and "unknown" (never 1970, never undefined behaviour) for a
// time that cannot be told.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <ctime>
#include <limits>
#include <string>

#include "glider/firmware/comms/surface_dialog.hpp"

using namespace glider::fw::comms;

namespace {

std::string ctime_of(double utc_s) {
  char text[40];
  format_ctime(utc_s, text, sizeof text);
  return text;
}

std::string segment_of(double utc_s) {
  char text[80];
  format_segment_name(text, sizeof text, "unit_345", utc_s, 7, 12);
  return text;
}

std::string dialog_with_abort_at(double utc_s) {
  DialogSnapshot s;
  s.vehicle_name = "unit_345";
  s.utc_s = 1764222012.0;
  s.aborts.total = 1;
  s.aborts.last_cause = glider::fw::AbortCause::kOverdepth;
  s.aborts.last_time_utc_s = utc_s;
  DialogQueue out;
  print_dialog(s, out);
  std::string text;
  while (!out.empty()) {
    const auto chunk = out.front();
    text.append(reinterpret_cast<const char*>(chunk.data()), chunk.size());
    out.consume(chunk.size());
  }
  return text;
}

}  // namespace

TEST_GROUP(CommsDialogTime){};

TEST(CommsDialogTime, CtimeAsSlocumPrintsIt) {
  STRCMP_EQUAL("Thu Nov 27 05:40:12 2025", ctime_of(1764222012.9).c_str());  // truncated, not rounded
  STRCMP_EQUAL("Sun Mar  1 00:00:00 2026", ctime_of(1772323200.0).c_str());
  STRCMP_EQUAL("Thu Feb 29 23:59:59 2024", ctime_of(1709251199.0).c_str());  // a leap day
  STRCMP_EQUAL("Thu Jan  1 00:00:00 1970", ctime_of(0.0).c_str());
}

TEST(CommsDialogTime, SameTextAsGmtimeOverManyTimes) {
  // The old path (gmtime_r + strftime-like printf) as the reference, one
  // time every ~9.7 days over 1970..2100 and odd seconds in between.
  for (double t = 0.0; t < 4102444800.0; t += 839'999.7) {
    const std::time_t whole = static_cast<std::time_t>(std::floor(t));
    std::tm tm{};
    gmtime_r(&whole, &tm);
    char expected[40];
    std::strftime(expected, sizeof expected, "%a %b %e %H:%M:%S %Y", &tm);
    STRCMP_EQUAL(expected, ctime_of(t).c_str());
    char day[80];
    std::snprintf(day, sizeof day, "unit_345-%04d-%03d-7-12", tm.tm_year + 1900, tm.tm_yday);
    STRCMP_EQUAL(day, segment_of(t).c_str());
  }
}

TEST(CommsDialogTime, SegmentNameCountsDaysFromZero) {
  STRCMP_EQUAL("unit_345-2026-000-7-12", segment_of(1767225600.0).c_str());  // 2026-01-01T00:00:00Z
  STRCMP_EQUAL("unit_345-2025-364-7-12", segment_of(1767225599.0).c_str());  // the second before
  STRCMP_EQUAL("unit_345-2024-365-7-12", segment_of(1735689599.0).c_str());  // 31 Dec of a leap year
}

// Old code: gmtime of a NaN cast to time_t (undefined; here 1970 or a year
// near -292 billion), never a refusal.
TEST(CommsDialogTime, TimeThatCannotBeToldIsUnknown) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {nan, inf, -inf, -1.0, 1e300, 253402300800.0}) {
    STRCMP_EQUAL("unknown", ctime_of(bad).c_str());
    STRCMP_EQUAL("unit_345-unknown-7-12", segment_of(bad).c_str());
  }
  STRCMP_EQUAL("Fri Dec 31 23:59:59 9999", ctime_of(253402300799.0).c_str());
}

TEST(CommsDialogTime, AbortTimeIsIsoWithoutZone) {
  STRCMP_CONTAINS("ABORT HISTORY: last abort time: 2025-11-27T05:40:12\r\n",
                  dialog_with_abort_at(1764222012.5).c_str());
  STRCMP_CONTAINS("ABORT HISTORY: last abort time: unknown\r\n",
                  dialog_with_abort_at(std::numeric_limits<double>::quiet_NaN()).c_str());
}
