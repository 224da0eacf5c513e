// SPDX-License-Identifier: Apache-2.0
// The serial sensors' byte stream: the NMEA framer cuts it into lines, the
// GPS (GGA/RMC) and compass ($PTNTHPR) decoders read each one. Whatever the
// bytes, every accepted value must be finite and in range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "glider/hal_linux/nmea.hpp"
#include "glider/hal_linux/sentence_decoders.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace hl = glider::hal_linux;
  hl::NmeaFramer framer;
  hl::NmeaGpsDecoder gps;
  hl::CompassDecoder compass;
  glider::hal::Micros now = 0;
  framer.feed(std::string_view(reinterpret_cast<const char*>(data), size), [&](std::string_view line) {
    now += 1000;
    gps.decode(line, now);
    compass.decode(line, now);
  });
  const auto& fix = gps.latest();
  if (fix.valid && !(std::fabs(fix.latitude_deg) <= 90.0 && std::fabs(fix.longitude_deg) <= 180.0)) std::abort();
  const auto& attitude = compass.latest();
  if (attitude.valid && !(std::isfinite(attitude.heading_rad) && std::isfinite(attitude.pitch_rad))) std::abort();
  return 0;
}
