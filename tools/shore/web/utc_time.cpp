// SPDX-License-Identifier: Apache-2.0
#include "utc_time.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>

namespace glider::shore::web {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double from_fields(int year, int month, int day, int hour, int minute, double second) {
  if (year < 1970 || year > 9999 || month < 1 || month > 12 || day < 1 || day > 31 || hour < 0 || hour > 23 ||
      minute < 0 || minute > 59 || !(second >= 0.0 && second < 61.0)) {
    return kNaN;
  }
  std::tm tm{};
  tm.tm_year = year - 1900;
  tm.tm_mon = month - 1;
  tm.tm_mday = day;
  tm.tm_hour = hour;
  tm.tm_min = minute;
  return static_cast<double>(::timegm(&tm)) + second;
}

}  // namespace

double parse_utc(const std::string& text) {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, used = 0;
  double second = 0.0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%n", &year, &month, &day, &hour, &minute, &second, &used) !=
          6 ||
      static_cast<std::size_t>(used) + 1 != text.size() || text.back() != 'Z') {
    return kNaN;
  }
  return from_fields(year, month, day, hour, minute, second);
}

double parse_call_id(const std::string& id) {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0, used = 0;
  if (id.size() < 15 ||
      std::sscanf(id.c_str(), "%4d%2d%2dT%2d%2d%2d%n", &year, &month, &day, &hour, &minute, &second, &used) != 6 ||
      used != 15) {
    return kNaN;
  }
  return from_fields(year, month, day, hour, minute, second);
}

std::string format_utc(double unix_seconds) {
  if (!std::isfinite(unix_seconds)) return "";
  const std::time_t t = static_cast<std::time_t>(std::floor(unix_seconds));
  std::tm tm{};
  ::gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

}  // namespace glider::shore::web
