// SPDX-License-Identifier: Apache-2.0
#include "glider/hal_linux/sentence_decoders.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "glider/units.hpp"

namespace glider::hal_linux {
namespace {

// Checks the sentence; counts the reason when it is not usable.
bool checked(std::string_view line, NmeaSentence& sentence, SentenceStats& stats) {
  switch (check_nmea(line, sentence)) {
    case NmeaCheck::kOk:
      return true;
    case NmeaCheck::kNoChecksum:
      ++stats.no_checksum;
      return false;
    case NmeaCheck::kBadChecksum:
      ++stats.bad_checksum;
      return false;
    case NmeaCheck::kMalformed:
      ++stats.malformed;
      return false;
  }
  return false;
}

// GGA fix qualities that are a measured position (1 GPS, 2 DGPS, 3 PPS,
// 4 RTK, 5 float RTK); 6 is dead reckoning, 7 manual input, 8 simulation.
bool measured_quality(int quality) { return quality >= 1 && quality <= 5; }

// "hhmmss[.ss]" -> seconds of the UTC day; NaN when absent or not a time.
double utc_time_of_day(std::string_view text) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (text.size() < 6) return nan;
  for (std::size_t i = 0; i < 6; ++i) {
    if (text[i] < '0' || text[i] > '9') return nan;
  }
  const auto two = [&text](std::size_t at) { return (text[at] - '0') * 10 + (text[at + 1] - '0'); };
  const int hours = two(0), minutes = two(2);
  const auto seconds = nmea_number(text.substr(4));                              // "ss" or "ss.ss"
  if (hours > 23 || minutes > 59 || !seconds || !(*seconds < 61.0)) return nan;  // 60: a leap second
  return hours * 3600.0 + minutes * 60.0 + *seconds;
}

}  // namespace

void NmeaGpsDecoder::lose_fix() {
  fix_.valid = false;
  ++stats_.no_fix;
}

void NmeaGpsDecoder::decode(std::string_view line, hal::Micros received_us) {
  NmeaSentence s;
  if (!checked(line, s, stats_)) return;
  if (s.formatter() == "GGA") {
    gga(s, received_us);
  } else if (s.formatter() == "RMC") {
    rmc(s, received_us);
  } else {
    ++stats_.other;
  }
}

// $--GGA,time,lat,N,lon,E,quality,satellites,hdop,altitude,M,geoid,M,age,station
void NmeaGpsDecoder::gga(const NmeaSentence& s, hal::Micros received_us) {
  if (s.count < 9) {
    ++stats_.malformed;
    return;
  }
  const auto quality = nmea_integer(s.field(6));
  if (!quality) {
    ++stats_.malformed;
    return;
  }
  if (!measured_quality(*quality)) {
    lose_fix();
    return;
  }
  const auto latitude = nmea_coordinate(s.field(2), s.field(3), 90.0);
  const auto longitude = nmea_coordinate(s.field(4), s.field(5), 180.0);
  const auto satellites = nmea_integer(s.field(7));
  const auto hdop = nmea_number(s.field(8));
  if (!latitude || !longitude || !satellites || !hdop) {
    ++stats_.malformed;
    return;
  }
  // Fewer than 4 satellites is no 3-D fix; an HDOP of 0 or above 50 is nonsense.
  if (*satellites < 4 || *satellites > 99 || !(*hdop > 0.0 && *hdop <= 50.0)) {
    ++stats_.implausible;
    return;
  }
  fix_ = {*latitude, *longitude, *quality, *satellites, *hdop, received_us, true, utc_time_of_day(s.field(1))};
  ++stats_.accepted;
}

// $--RMC,time,status,lat,N,lon,E,speed,course,date,variation,E[,mode]
void NmeaGpsDecoder::rmc(const NmeaSentence& s, hal::Micros received_us) {
  if (s.count < 10) {
    ++stats_.malformed;
    return;
  }
  const std::string_view status = s.field(2);
  const std::string_view mode = s.field(12);
  if (status != "A" || mode == "N" || mode == "E") {  // V: warning; mode N none, E estimated
    if (status != "A" && status != "V") {
      ++stats_.malformed;
      return;
    }
    lose_fix();
    return;
  }
  const auto latitude = nmea_coordinate(s.field(3), s.field(4), 90.0);
  const auto longitude = nmea_coordinate(s.field(5), s.field(6), 180.0);
  if (!latitude || !longitude) {
    ++stats_.malformed;
    return;
  }
  // RMC has no quality, satellites or HDOP: it refreshes a GGA fix only.
  if (!fix_.valid) {
    ++stats_.other;
    return;
  }
  fix_.latitude_deg = *latitude;
  fix_.longitude_deg = *longitude;
  fix_.time_us = received_us;
  ++stats_.accepted;
}

void CompassDecoder::decode(std::string_view line, hal::Micros received_us) {
  NmeaSentence s;
  if (!checked(line, s, stats_)) return;
  if (s.address() != "PTNTHPR") {
    ++stats_.other;
    return;
  }
  if (s.count != 7) {
    ++stats_.malformed;
    return;
  }
  const auto heading = nmea_number(s.field(1));
  const auto pitch = nmea_number(s.field(3));
  const auto roll = nmea_number(s.field(5));
  if (!heading || !pitch || !roll) {
    ++stats_.malformed;
    return;
  }
  if (s.field(2) != "N" || s.field(4) != "N" || s.field(6) != "N") {
    ++stats_.no_fix;  // the compass flags the reading (magnetic alarm, tilt out of range, tuning)
    return;
  }
  if (*heading < 0.0 || *heading >= 360.0 || std::abs(*pitch) > 90.0 || std::abs(*roll) > 180.0) {
    ++stats_.implausible;
    return;
  }
  sample_ = {deg_to_rad(*pitch), deg_to_rad(*roll), deg_to_rad(*heading), received_us, true};
  ++stats_.accepted;
}

}  // namespace glider::hal_linux
