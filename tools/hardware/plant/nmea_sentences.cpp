// SPDX-License-Identifier: Apache-2.0
#include "nmea_sentences.hpp"

#include <cmath>
#include <cstdio>

#include "glider/units.hpp"

namespace glider::plant {
namespace {

std::string hhmmss(double utc_s) {
  const double day = std::fmod(std::max(utc_s, 0.0), 86400.0);
  const int h = static_cast<int>(day / 3600.0);
  const int m = static_cast<int>((day - 3600.0 * h) / 60.0);
  const double s = day - 3600.0 * h - 60.0 * m;
  char text[16];
  std::snprintf(text, sizeof text, "%02d%02d%05.2f", h, m, std::floor(s * 100.0) / 100.0);
  return text;
}

// ddmm.mmmmm / dddmm.mmmmm and the hemisphere: 1e-5 minute is 2 cm.
std::string coordinate(double degrees, int degree_digits, char positive, char negative) {
  const double magnitude = std::abs(degrees);
  int whole = static_cast<int>(magnitude);
  double minutes = std::round((magnitude - whole) * 60.0 * 1e5) / 1e5;
  if (minutes >= 60.0) {
    minutes -= 60.0;
    ++whole;
  }
  char text[32];
  std::snprintf(text, sizeof text, "%0*d%08.5f,%c", degree_digits, whole, minutes, degrees < 0.0 ? negative : positive);
  return text;
}

}  // namespace

std::string nmea_sentence(const std::string& body) {
  unsigned sum = 0;
  for (const char c : body) sum ^= static_cast<unsigned char>(c);
  char tail[8];
  std::snprintf(tail, sizeof tail, "*%02X\r\n", sum);
  return "$" + body + tail;
}

std::string gga_fix(const hal::GpsFix& fix, double utc_s) {
  char tail[64];
  std::snprintf(tail, sizeof tail, ",%d,%02d,%.1f,0.0,M,0.0,M,,", fix.quality, fix.satellites, fix.hdop);
  return nmea_sentence("GPGGA," + hhmmss(utc_s) + "," + coordinate(fix.latitude_deg, 2, 'N', 'S') + "," +
                       coordinate(fix.longitude_deg, 3, 'E', 'W') + tail);
}

std::string gga_no_fix(double utc_s) { return nmea_sentence("GPGGA," + hhmmss(utc_s) + ",,,,,0,00,99.9,,M,,M,,"); }

std::string rmc_fix(const hal::GpsFix& fix, double utc_s) {
  return nmea_sentence("GPRMC," + hhmmss(utc_s) + ",A," + coordinate(fix.latitude_deg, 2, 'N', 'S') + "," +
                       coordinate(fix.longitude_deg, 3, 'E', 'W') + ",0.0,0.0,241126,,,A");
}

std::string ptnthpr(const hal::AttitudeSample& sample) {
  double heading = std::round(rad_to_deg(sample.heading_rad) * 10.0) / 10.0;
  if (heading >= 360.0) heading -= 360.0;  // 359.96 rounds to 360.0, which is 0.0
  char body[64];
  std::snprintf(body, sizeof body, "PTNTHPR,%.1f,N,%.1f,N,%.1f,N", heading, rad_to_deg(sample.pitch_rad),
                rad_to_deg(sample.roll_rad));
  return nmea_sentence(body);
}

}  // namespace glider::plant
