// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the serial sensors' sentences mean: NMEA 0183 GGA and RMC for the
// GPS, $PTNTHPR for the compass (docs in boards/serial_sensors.md). Pure code
// (no I/O, no allocation): a line in, the newest good value out, every
// rejected line counted by its reason.
#include <cstdint>
#include <string_view>

#include "glider/hal/attitude_sensor.hpp"
#include "glider/hal/gps.hpp"
#include "glider/hal_linux/nmea.hpp"

namespace glider::hal_linux {

struct SentenceStats {
  std::uint64_t accepted = 0;
  std::uint64_t bad_checksum = 0;
  std::uint64_t no_checksum = 0;
  std::uint64_t malformed = 0;    // framing, field count, fields that are not numbers
  std::uint64_t implausible = 0;  // numbers out of their range
  std::uint64_t no_fix = 0;       // the sensor itself says the value is not good
  std::uint64_t other = 0;        // well-formed sentences this decoder does not use

  std::uint64_t rejected() const { return bad_checksum + no_checksum + malformed + implausible + no_fix; }
};

// GGA gives the fix (position, quality, satellites, HDOP); RMC confirms or
// withdraws it (status A / V, FAA mode N). A GGA with quality 0, an RMC
// with status V, or quality 6-8 (dead reckoning, manual, simulator) makes
// the fix invalid: the receiver says it has no position now.
class NmeaGpsDecoder {
 public:
  void decode(std::string_view line, hal::Micros received_us);
  const hal::GpsFix& latest() const { return fix_; }
  const SentenceStats& stats() const { return stats_; }

 private:
  void gga(const NmeaSentence& s, hal::Micros received_us);
  void rmc(const NmeaSentence& s, hal::Micros received_us);
  void lose_fix();

  hal::GpsFix fix_;
  SentenceStats stats_;
};

// The compass' heading, pitch and roll (True North Technologies Revolution
// style, as on Slocum gliders):
//   $PTNTHPR,<heading deg>,<status>,<pitch deg>,<status>,<roll deg>,<status>*hh
// Status N is normal; any other letter (alarm, warning, tuning) rejects the
// sentence. Pitch + nose up, roll + starboard down, heading true.
class CompassDecoder {
 public:
  void decode(std::string_view line, hal::Micros received_us);
  const hal::AttitudeSample& latest() const { return sample_; }
  const SentenceStats& stats() const { return stats_; }

 private:
  hal::AttitudeSample sample_;
  SentenceStats stats_;
};

}  // namespace glider::hal_linux
