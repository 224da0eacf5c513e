// SPDX-License-Identifier: Apache-2.0
// glider/utc_time.hpp against a table of texts: valid ones with their seconds
// (from `date -u -d TEXT +%s`), invalid ones with the reason, and the
// calendar's edges (leap years, month ends, the range of the form).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "glider/utc_time.hpp"

namespace {

using glider::utc::Parsed;
using glider::utc::Rules;

struct Valid {
  const char* text;
  std::int64_t whole_s;
  double fraction_s;
};

struct Invalid {
  const char* text;
  const char* problem;  // a word the reason must contain
};

void check_valid(const Parsed& p, const Valid& v) {
  const std::string what = std::string("'") + v.text + "': " + p.problem;
  CHECK_TEXT(p.ok, what.c_str());
  CHECK_EQUAL_TEXT(v.whole_s, p.whole_s, v.text);
  DOUBLES_EQUAL(v.fraction_s, p.fraction_s, 1e-12);
}

void check_invalid(const Parsed& p, const Invalid& v) {
  CHECK_TEXT(!p.ok, v.text);
  const std::string what = std::string("'") + v.text + "' gave '" + p.problem + "', expected '" + v.problem + "'";
  CHECK_TEXT(std::strstr(p.problem, v.problem) != nullptr, what.c_str());
}

}  // namespace

TEST_GROUP(BaseUtcTime){};

TEST(BaseUtcTime, IsoValidTable) {
  const Valid table[] = {
      {"1970-01-01T00:00:00Z", 0, 0.0},
      {"2026-11-27T05:40:12Z", 1795758012, 0.0},
      {"2026-11-27T05:40:12.5Z", 1795758012, 0.5},
      {"2026-11-27T05:40:12.123456789Z", 1795758012, 0.123456789},
      {"2000-02-29T12:00:00Z", 951825600, 0.0},  // leap year (divisible by 400)
      {"2024-02-29T23:59:59Z", 1709251199, 0.0},
      {"2026-12-31T23:59:59Z", 1798761599, 0.0},
      {"2027-01-01T00:00:00Z", 1798761600, 0.0},
      {"2038-01-19T03:14:08Z", 2147483648, 0.0},  // past 32-bit time_t
      {"9999-12-31T23:59:59Z", 253402300799, 0.0},
  };
  for (const Valid& v : table) check_valid(glider::utc::parse_iso(v.text), v);
}

TEST(BaseUtcTime, IsoInvalidTable) {
  const Invalid table[] = {
      {"2026-02-30T00:00:00Z", "day"},  // timegm would say 2 March
      {"2026-02-29T00:00:00Z", "day"},  // 2026 is not a leap year
      {"2100-02-29T00:00:00Z", "day"},  // divisible by 100, not by 400
      {"2026-04-31T00:00:00Z", "day"},
      {"2026-01-00T00:00:00Z", "day"},
      {"2026-13-01T00:00:00Z", "month"},
      {"2026-00-01T00:00:00Z", "month"},
      {"2026-07-02T24:00:00Z", "hour"},
      {"2026-07-02T23:60:00Z", "minute"},
      {"2026-12-31T23:59:60Z", "second"},  // POSIX time has no leap second
      {"1969-12-31T23:59:59Z", "year"},
      {"2026-07-02T11:27:05", "form"},   // no zone
      {"2026-07-02 11:27:05Z", "form"},  // no T
      {"2026-7-02T11:27:05Z", "form"},   // one-digit month
      {"2026-07-02T11:27:05+00:00", "form"},
      {"2026-07-02T11:27:05Z ", "after"},  // trailing junk
      {"2026-07-02T11:27:05Zjunk", "after"},
      {"2026-07-02T11:27:05.Z", "form"},  // a point without digits
      {"2026-07-02T11:27:05.1234567890Z", "digits"},
      {"-026-07-02T11:27:05Z", "form"},
      {"nan", "form"},
      {"", "form"},
  };
  for (const Invalid& v : table) check_invalid(glider::utc::parse_iso(v.text), v);
}

TEST(BaseUtcTime, IsoRules) {
  const Rules launch{2000, 2099, 0};
  check_valid(glider::utc::parse_iso("2099-12-31T23:59:59Z", launch), {"2099", 4102444799, 0.0});
  check_invalid(glider::utc::parse_iso("1999-12-31T23:59:59Z", launch), {"1999", "year"});
  check_invalid(glider::utc::parse_iso("2100-01-01T00:00:00Z", launch), {"2100", "year"});
  check_invalid(glider::utc::parse_iso("2026-07-02T11:27:05.5Z", launch), {"fraction", "fraction"});
  const Rules millis{1970, 9999, 3};
  check_valid(glider::utc::parse_iso("2026-07-02T11:27:05.125Z", millis), {"ms", 1782991625, 0.125});
  check_invalid(glider::utc::parse_iso("2026-07-02T11:27:05.1250Z", millis), {"us", "digits"});
}

TEST(BaseUtcTime, CompactTable) {
  check_valid(glider::utc::parse_compact("20261127T054608"), {"id", 1795758368, 0.0});
  check_valid(glider::utc::parse_compact("20240229T000000"), {"leap", 1709164800, 0.0});
  check_invalid(glider::utc::parse_compact("20260229T000000"), {"20260229", "day"});
  check_invalid(glider::utc::parse_compact("20261127T054608_0001"), {"id with counter", "after"});
  check_invalid(glider::utc::parse_compact("20261127 054608"), {"space", "form"});
  check_invalid(glider::utc::parse_compact("20261127T246000"), {"hour 24", "hour"});
}

TEST(BaseUtcTime, CtimeTable) {
  const Valid valid[] = {
      {"Fri Nov 27 05:40:12 2026", 1795758012, 0.0},
      {"Thu Jul  2 11:27:05 2026", 1782991625, 0.0},  // asctime's space-padded day
      {"Thu Jul 2 11:27:05 2026", 1782991625, 0.0},
      {"Thu Jul 02 11:27:05 2026", 1782991625, 0.0},
      {"Thu Feb 29 00:00:00 2024", 1709164800, 0.0},
  };
  for (const Valid& v : valid) check_valid(glider::utc::parse_ctime(v.text), v);
  const Invalid invalid[] = {
      {"Sat Nov 27 05:40:12 2026", "weekday"},  // 27 Nov 2026 is a Friday
      {"Fri Feb 30 05:40:12 2026", "day"},     {"Fri Nov 27 05:40:12 2026 ", "after"},
      {"Fri Nov 27 25:40:12 2026", "hour"},    {"Fri Nov 27 05:40:12", "form"},
      {"Fri Nvm 27 05:40:12 2026", "form"},    {"fri nov 27 05:40:12 2026", "form"},
      {"Fri Nov 127 05:40:12 2026", "form"},
  };
  for (const Invalid& v : invalid) check_invalid(glider::utc::parse_ctime(v.text), v);
}

TEST(BaseUtcTime, FormatIso) {
  STRCMP_EQUAL("1970-01-01T00:00:00Z", glider::utc::format_iso(0.0).c_str());
  STRCMP_EQUAL("2026-11-27T05:40:12Z", glider::utc::format_iso(1795758012.0).c_str());
  // Truncated toward the earlier time at the chosen precision.
  STRCMP_EQUAL("2026-11-27T05:40:12Z", glider::utc::format_iso(1795758012.999).c_str());
  STRCMP_EQUAL("2026-11-27T05:40:12.9Z", glider::utc::format_iso(1795758012.99, 1).c_str());
  STRCMP_EQUAL("2026-11-27T05:40:12.300Z", glider::utc::format_iso(1795758012.3, 3).c_str());  // not .299
  STRCMP_EQUAL("2026-11-27T05:40:12.000001Z", glider::utc::format_iso(1795758012.000001, 6).c_str());
  STRCMP_EQUAL("1969-12-31T23:59:59.500Z", glider::utc::format_iso(-0.5, 3).c_str());
  STRCMP_EQUAL("2024-02-29T23:59:59Z", glider::utc::format_iso(1709251199.0).c_str());
  STRCMP_EQUAL("9999-12-31T23:59:59Z", glider::utc::format_iso(253402300799.0).c_str());
  STRCMP_EQUAL("", glider::utc::format_iso(253402300800.0).c_str());  // year 10000: not four digits
  STRCMP_EQUAL("", glider::utc::format_iso(std::nan("")).c_str());
  STRCMP_EQUAL("", glider::utc::format_iso(HUGE_VAL).c_str());
  STRCMP_EQUAL("", glider::utc::format_iso(1.0, 7).c_str());  // beyond a double's resolution at today's times
  STRCMP_EQUAL("20261127T054012", glider::utc::format_compact(1795758012.7).c_str());
  STRCMP_EQUAL("Thu Jul  2 11:27:05 2026", glider::utc::format_ctime(1782991625).c_str());
  char small[8];
  LONGS_EQUAL(0, glider::utc::write_iso(small, sizeof small, 0.0));  // does not fit: nothing claimed
  char fits[21];
  LONGS_EQUAL(20, glider::utc::write_iso(fits, sizeof fits, 0.0));
}

TEST(BaseUtcTime, RoundTripEveryDayOf400Years) {
  // Every day of a Gregorian cycle: format then parse gives the same second, and the
  // calendar fields agree with the day count (so leap days are where they should be).
  int leap_days = 0;
  for (std::int64_t day = glider::utc::days_from_civil(2000, 1, 1);
       day < glider::utc::days_from_civil(2000, 1, 1) + 146097; ++day) {
    const std::int64_t s = day * 86400 + 3723;  // 01:02:03
    const std::string iso = glider::utc::format_iso(static_cast<double>(s));
    const Parsed back = glider::utc::parse_iso(iso);
    CHECK_TEXT(back.ok && back.whole_s == s, iso.c_str());
    const Parsed ctime = glider::utc::parse_ctime(glider::utc::format_ctime(s));
    CHECK_TEXT(ctime.ok && ctime.whole_s == s, iso.c_str());
    if (iso.compare(5, 5, "02-29") == 0) ++leap_days;
  }
  LONGS_EQUAL(97, leap_days);  // 100 - 3 in 400 years
}
