// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/log/slocum_format.hpp"

#include <array>
#include <cstdio>

namespace glider::fw {
namespace {

constexpr std::array<std::uint32_t, 256> kCrcTable = [] {
  std::array<std::uint32_t, 256> table{};
  for (std::uint32_t n = 0; n < 256; ++n) {
    std::uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
    table[n] = c;
  }
  return table;
}();

// Days since 1970-01-01 to the civil date (H. Hinnant's algorithm).
void civil_from_days(std::int64_t z, int& year, int& month, int& day) {
  z += 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const auto doe = static_cast<unsigned>(z - era * 146097);
  const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
  const unsigned mp = (5 * doy + 2) / 153;
  day = static_cast<int>(doy - (153 * mp + 2) / 5 + 1);
  month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  year = static_cast<int>(static_cast<std::int64_t>(yoe) + era * 400 + (month <= 2 ? 1 : 0));
}

bool leap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

}  // namespace

std::string slocum_sensor_list(const SlocumSelection& selection) {
  std::string list;
  int stored = 0;
  for (std::size_t i = 0; i < kSlocumFlightSensors.size(); ++i) {
    const SlocumSensor& sensor = kSlocumFlightSensors[i];
    const bool in = selection.logged[i];
    char head[32];
    const int n = std::snprintf(head, sizeof head, "s: %s%5d%5d%2d ", in ? "T" : "F", static_cast<int>(i),
                                in ? stored : -1, static_cast<int>(sensor.bytes));
    list.append(head, static_cast<std::size_t>(n));
    list.append(sensor.name).append(" ").append(sensor.unit).append("\n");
    if (in) ++stored;
  }
  return list;
}

std::uint32_t slocum_list_crc(std::string_view list) {
  std::uint32_t c = 0xFFFFFFFFU;
  for (const char byte : list) c = kCrcTable[(c ^ static_cast<unsigned char>(byte)) & 0xFFU] ^ (c >> 8);
  return c;  // not inverted: Slocum's sensor_list_crc
}

UtcDate utc_date(hal::Micros utc_us) {
  std::int64_t seconds = utc_us / hal::kMicrosPerSecond;
  if (utc_us % hal::kMicrosPerSecond < 0) --seconds;
  std::int64_t days = seconds / 86400;
  std::int64_t of_day = seconds % 86400;
  if (of_day < 0) {
    of_day += 86400;
    --days;
  }
  UtcDate date;
  civil_from_days(days, date.year, date.month, date.day);
  static constexpr std::array<int, 12> kDaysBefore = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  date.day_of_year = kDaysBefore[static_cast<std::size_t>(date.month - 1)] + date.day - 1 +
                     (date.month > 2 && leap(date.year) ? 1 : 0);
  date.weekday = static_cast<int>(((days % 7) + 11) % 7);  // 1970-01-01 was a Thursday (4)
  date.hour = static_cast<int>(of_day / 3600);
  date.minute = static_cast<int>(of_day / 60 % 60);
  date.second = static_cast<int>(of_day % 60);
  return date;
}

std::size_t format_fileopen_time(const UtcDate& date, char* out) {
  static constexpr std::array<const char*, 7> kDays = {"Sun", "Mon", "Tue", "Wed", "Thu", "Fri", "Sat"};
  static constexpr std::array<const char*, 12> kMonths = {"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                                          "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};
  // ctime's "%.3s %.3s%3d %.2d:%.2d:%.2d %d" with the blanks as '_'.
  const char* weekday = kDays[static_cast<std::size_t>(date.weekday)];
  const char* month = kMonths[static_cast<std::size_t>(date.month - 1)];
  const int n = date.day < 10 ? std::snprintf(out, 32, "%s_%s__%d_%02d:%02d:%02d_%d", weekday, month, date.day,
                                              date.hour, date.minute, date.second, date.year)
                              : std::snprintf(out, 32, "%s_%s_%d_%02d:%02d:%02d_%d", weekday, month, date.day,
                                              date.hour, date.minute, date.second, date.year);
  return n > 0 ? static_cast<std::size_t>(n) : 0;
}

}  // namespace glider::fw
