// SPDX-License-Identifier: Apache-2.0
#include "glider/utc_time.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace glider::utc {
namespace {

constexpr std::int64_t kSecondsPerDay = 86400;
constexpr std::array<const char*, 7> kWeekdays{"Sun", "Mon", "Tue", "Wed", "Thu", "Fri", "Sat"};
constexpr std::array<const char*, 12> kMonths{"Jan", "Feb", "Mar", "Apr", "May", "Jun",
                                              "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};

// Reads the text left to right; every step fails (false) without moving on a mismatch.
class Cursor {
 public:
  explicit Cursor(std::string_view text) : text_(text) {}
  bool at_end() const { return pos_ == text_.size(); }
  bool next_is(char c) const { return pos_ < text_.size() && text_[pos_] == c; }
  bool literal(char c) {
    if (!next_is(c)) return false;
    ++pos_;
    return true;
  }
  // Exactly `count` decimal digits.
  bool digits(int count, int& value) {
    value = 0;
    for (int i = 0; i < count; ++i) {
      if (pos_ >= text_.size() || text_[pos_] < '0' || text_[pos_] > '9') return false;
      value = value * 10 + (text_[pos_++] - '0');
    }
    return true;
  }
  // One of the three-letter names; its index.
  template <std::size_t N>
  bool name(const std::array<const char*, N>& names, int& index) {
    if (text_.size() - pos_ < 3) return false;
    for (std::size_t i = 0; i < N; ++i) {
      if (text_.substr(pos_, 3) == names[i]) {
        index = static_cast<int>(i);
        pos_ += 3;
        return true;
      }
    }
    return false;
  }
  // Up to `max_digits` digits after the '.' just read; false when none or too many.
  bool fraction(int max_digits, double& value, bool& too_many) {
    std::int64_t numerator = 0;
    std::int64_t denominator = 1;
    int count = 0;
    while (pos_ < text_.size() && text_[pos_] >= '0' && text_[pos_] <= '9') {
      if (count == max_digits) {
        too_many = true;
        return false;
      }
      numerator = numerator * 10 + (text_[pos_++] - '0');
      denominator *= 10;
      ++count;
    }
    value = static_cast<double>(numerator) / static_cast<double>(denominator);
    return count > 0;
  }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
};

Parsed failed(const char* problem) {
  Parsed p;
  p.problem = problem;
  return p;
}

// The fields' ranges and the calendar, then the seconds.
Parsed checked(const Civil& c, double fraction, const Rules& rules) {
  if (c.year < rules.min_year || c.year > rules.max_year) return failed("year outside the allowed range");
  if (c.month < 1 || c.month > 12) return failed("month outside [1, 12]");
  if (c.day < 1 || c.day > days_in_month(c.year, c.month)) return failed("day does not exist in that month");
  if (c.hour > 23) return failed("hour outside [0, 23]");
  if (c.minute > 59) return failed("minute outside [0, 59]");
  // POSIX time has no leap second: 23:59:60 cannot be told from the next minute's 00.
  if (c.second > 59) return failed("second outside [0, 59]");
  Parsed p;
  p.ok = true;
  p.whole_s = days_from_civil(c.year, c.month, c.day) * kSecondsPerDay + std::int64_t{c.hour} * 3600 +
              std::int64_t{c.minute} * 60 + c.second;
  p.fraction_s = fraction;
  return p;
}

// "HH:MM:SS" (the separators given).
bool time_of_day(Cursor& in, Civil& c, char separator) {
  if (!in.digits(2, c.hour)) return false;
  if (separator != 0 && !in.literal(separator)) return false;
  if (!in.digits(2, c.minute)) return false;
  if (separator != 0 && !in.literal(separator)) return false;
  return in.digits(2, c.second);
}

// Seconds -> whole seconds and fraction units at `decimals`, truncated after absorbing
// the double's representation error (a few ulps of the value).
bool split(double seconds, int decimals, std::int64_t& whole, std::int64_t& units, std::int64_t& scale) {
  // Years 0..9999 (the four digits of the form): a bound that keeps every step exact.
  constexpr double kFirst = -62167219200.0;  // 0000-01-01T00:00:00Z
  constexpr double kEnd = 253402300800.0;    // 10000-01-01T00:00:00Z
  if (!std::isfinite(seconds) || decimals < 0 || decimals > 6 || seconds < kFirst || seconds >= kEnd) return false;
  scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10;
  const double ulp = std::nextafter(std::fabs(seconds), std::numeric_limits<double>::infinity()) - std::fabs(seconds);
  const double floor_s = std::floor(seconds);
  whole = static_cast<std::int64_t>(floor_s);
  units = static_cast<std::int64_t>(std::floor((seconds - floor_s + 4.0 * ulp) * static_cast<double>(scale)));
  if (units >= scale) {
    whole += units / scale;
    units %= scale;
  }
  return static_cast<double>(whole) < kEnd;
}

std::size_t written(int length, std::size_t size) {
  return length > 0 && static_cast<std::size_t>(length) < size ? static_cast<std::size_t>(length) : 0;
}

}  // namespace

bool is_leap_year(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

int days_in_month(int year, int month) {
  constexpr std::array<int, 12> kDays{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  if (month < 1 || month > 12) return 0;
  return month == 2 && is_leap_year(year) ? 29 : kDays[static_cast<std::size_t>(month - 1)];
}

std::int64_t days_from_civil(int year, int month, int day) {
  const std::int64_t y = year - (month <= 2 ? 1 : 0);
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t year_of_era = y - era * 400;
  const std::int64_t day_of_year = (153 * (month + (month > 2 ? -3 : 9)) + 2) / 5 + day - 1;
  const std::int64_t day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

Civil civil_from_seconds(std::int64_t seconds) {
  std::int64_t days = seconds / kSecondsPerDay;
  std::int64_t rest = seconds % kSecondsPerDay;
  if (rest < 0) {
    rest += kSecondsPerDay;
    --days;
  }
  const std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t day_of_era = z - era * 146097;
  const std::int64_t year_of_era = (day_of_era - day_of_era / 1460 + day_of_era / 36524 - day_of_era / 146096) / 365;
  const std::int64_t day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
  const std::int64_t mp = (5 * day_of_year + 2) / 153;
  Civil c;
  c.day = static_cast<int>(day_of_year - (153 * mp + 2) / 5 + 1);
  c.month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  c.year = static_cast<int>(year_of_era + era * 400 + (c.month <= 2 ? 1 : 0));
  c.hour = static_cast<int>(rest / 3600);
  c.minute = static_cast<int>(rest % 3600 / 60);
  c.second = static_cast<int>(rest % 60);
  return c;
}

int weekday(std::int64_t seconds) {
  std::int64_t days = seconds / kSecondsPerDay;
  if (seconds % kSecondsPerDay < 0) --days;
  return static_cast<int>(((days % 7) + 7 + 4) % 7);  // 1970-01-01 was a Thursday
}

Parsed parse_iso(std::string_view text, const Rules& rules) {
  constexpr const char* kForm = "not the form YYYY-MM-DDTHH:MM:SS[.fff]Z";
  Cursor in(text);
  Civil c;
  if (!in.digits(4, c.year) || !in.literal('-') || !in.digits(2, c.month) || !in.literal('-') || !in.digits(2, c.day) ||
      !in.literal('T') || !time_of_day(in, c, ':')) {
    return failed(kForm);
  }
  double fraction = 0.0;
  if (in.literal('.')) {
    if (rules.max_fraction_digits <= 0) return failed("no fraction of a second allowed");
    bool too_many = false;
    if (!in.fraction(rules.max_fraction_digits, fraction, too_many)) {
      return failed(too_many ? "too many digits of a second" : kForm);
    }
  }
  if (!in.literal('Z')) return failed(kForm);
  if (!in.at_end()) return failed("text after the time");
  return checked(c, fraction, rules);
}

Parsed parse_compact(std::string_view text, const Rules& rules) {
  Cursor in(text);
  Civil c;
  if (!in.digits(4, c.year) || !in.digits(2, c.month) || !in.digits(2, c.day) || !in.literal('T') ||
      !time_of_day(in, c, 0)) {
    return failed("not the form YYYYMMDDTHHMMSS");
  }
  if (!in.at_end()) return failed("text after the time");
  return checked(c, 0.0, rules);
}

Parsed parse_ctime(std::string_view text, const Rules& rules) {
  constexpr const char* kForm = "not the form 'Www Mmm DD HH:MM:SS YYYY'";
  Cursor in(text);
  Civil c;
  int day_name = 0;
  int month_index = 0;
  if (!in.name(kWeekdays, day_name) || !in.literal(' ') || !in.name(kMonths, month_index) || !in.literal(' ')) {
    return failed(kForm);
  }
  c.month = month_index + 1;
  // asctime pads the day with a space ("Nov  6"); some writers use "Nov 6" or "Nov 06".
  if (in.literal(' ')) {
    if (!in.digits(1, c.day)) return failed(kForm);
  } else {
    int tens = 0;
    int ones = 0;
    if (!in.digits(1, tens)) return failed(kForm);
    c.day = in.digits(1, ones) ? tens * 10 + ones : tens;
  }
  if (!in.literal(' ') || !time_of_day(in, c, ':') || !in.literal(' ') || !in.digits(4, c.year)) return failed(kForm);
  if (!in.at_end()) return failed("text after the time");
  Parsed p = checked(c, 0.0, rules);
  if (p.ok && weekday(p.whole_s) != day_name) return failed("weekday is not the date's");
  return p;
}

std::size_t write_iso(char* out, std::size_t size, double seconds, int decimals) {
  std::int64_t whole = 0;
  std::int64_t units = 0;
  std::int64_t scale = 1;
  if (out == nullptr || size == 0 || !split(seconds, decimals, whole, units, scale)) return 0;
  const Civil c = civil_from_seconds(whole);
  const int length = decimals == 0
                         ? std::snprintf(out, size, "%04d-%02d-%02dT%02d:%02d:%02dZ", c.year, c.month, c.day, c.hour,
                                         c.minute, c.second)
                         : std::snprintf(out, size, "%04d-%02d-%02dT%02d:%02d:%02d.%0*lldZ", c.year, c.month, c.day,
                                         c.hour, c.minute, c.second, decimals, static_cast<long long>(units));
  return written(length, size);
}

std::size_t write_ctime(char* out, std::size_t size, std::int64_t seconds) {
  if (out == nullptr || size == 0) return 0;
  const Civil c = civil_from_seconds(seconds);
  if (c.year < 0 || c.year > 9999) return 0;
  const int length =
      std::snprintf(out, size, "%s %s %2d %02d:%02d:%02d %04d", kWeekdays[weekday(seconds)],
                    kMonths[static_cast<std::size_t>(c.month - 1)], c.day, c.hour, c.minute, c.second, c.year);
  return written(length, size);
}

std::string format_iso(double seconds, int decimals) {
  char text[40];
  return write_iso(text, sizeof text, seconds, decimals) > 0 ? std::string(text) : std::string();
}

std::string format_compact(double seconds) {
  std::int64_t whole = 0;
  std::int64_t units = 0;
  std::int64_t scale = 1;
  if (!split(seconds, 0, whole, units, scale)) return {};
  const Civil c = civil_from_seconds(whole);
  char text[32];
  const int length =
      std::snprintf(text, sizeof text, "%04d%02d%02dT%02d%02d%02d", c.year, c.month, c.day, c.hour, c.minute, c.second);
  return written(length, sizeof text) > 0 ? std::string(text) : std::string();
}

std::string format_ctime(std::int64_t seconds) {
  char text[40];
  return write_ctime(text, sizeof text, seconds) > 0 ? std::string(text) : std::string();
}

}  // namespace glider::utc
