// SPDX-License-Identifier: Apache-2.0
#pragma once
// Building NMEA sentences for the tests: the checksum of a body, and a
// whole sentence with a correct (or deliberately wrong) one.
#include <cstdio>
#include <string>

namespace glider::test {

inline unsigned nmea_checksum(const std::string& body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  return sum;
}

// "$BODY*HH\r\n"; `corrupt` flips the checksum.
inline std::string nmea(const std::string& body, bool corrupt = false) {
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", nmea_checksum(body) ^ (corrupt ? 0x5Au : 0u));
  return "$" + body + tail;
}

}  // namespace glider::test
