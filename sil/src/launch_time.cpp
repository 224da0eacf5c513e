// SPDX-License-Identifier: Apache-2.0
#include "glider/sil/launch_time.hpp"

#include <ctime>

namespace glider::sil {

bool parse_launch_utc(const std::string& text, std::int64_t& utc_s, std::string& why) {
  why = "is not a UTC time YYYY-MM-DDTHH:MM:SSZ with a year in [2000, 2099]";
  std::tm tm{};
  const char* end = text.size() == 20 ? ::strptime(text.c_str(), "%Y-%m-%dT%H:%M:%SZ", &tm) : nullptr;
  if (end == nullptr || *end != '\0' || tm.tm_year < 100 || tm.tm_year > 199) return false;
  const int day = tm.tm_mday;
  const int month = tm.tm_mon;
  const std::time_t t = ::timegm(&tm);
  // timegm normalises (30 February -> 2 March): a date that moved did not exist.
  std::tm back{};
  if (t == static_cast<std::time_t>(-1) || ::gmtime_r(&t, &back) == nullptr || back.tm_mday != day ||
      back.tm_mon != month) {
    why = "is not a calendar date (YYYY-MM-DDTHH:MM:SSZ, years [2000, 2099])";
    return false;
  }
  utc_s = static_cast<std::int64_t>(t);
  why.clear();
  return true;
}

}  // namespace glider::sil
