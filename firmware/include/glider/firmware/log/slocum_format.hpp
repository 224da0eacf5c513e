// SPDX-License-Identifier: Apache-2.0
#pragma once
// The text parts of a Slocum DINKUM binary file (encoding version 5) as a
// glider writes them (docs/slocum-binary.md): the sensor list (a line per
// sensor, the <crc>.cac cache), its CRC, the UTC date words of the names and
// headers. No allocation except slocum_sensor_list(), which runs at start-up.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "glider/firmware/log/slocum_list.hpp"
#include "glider/hal/time.hpp"

namespace glider::fw {

// The sensor list: for every sensor "s: T|F <index> <stored index or -1>
// <bytes> <name> <unit>\n" (printf "s: %s%5d%5d%2d %s %s\n"), T for the ones
// the file stores. Byte-identical in form to a glider's .cac.
std::string slocum_sensor_list(const SlocumSelection& selection);

// sensor_list_crc: the CRC-32 (IEEE 802.3 polynomial, reflected, initial
// value all ones) of the sensor list's bytes WITHOUT the final inversion.
// Checked against the six real caches in tests/data/real/dbd (their file
// names are their CRCs).
std::uint32_t slocum_list_crc(std::string_view list);

struct UtcDate {
  int year = 1970;
  int day_of_year = 0;  // 0-based, as in the glider's names (Jun 23 2016 is 174)
  int month = 1;        // 1..12
  int day = 1;          // 1..31
  int weekday = 4;      // 0 = Sunday
  int hour = 0, minute = 0, second = 0;
};
UtcDate utc_date(hal::Micros utc_us);

// fileopen_time: ctime's text with '_' for blanks ("Thu_Jun_23_17:50:39_2016",
// "Mon_Jan__5_..."). `out` has room for 32; returns the length.
std::size_t format_fileopen_time(const UtcDate& date, char* out);

}  // namespace glider::fw
