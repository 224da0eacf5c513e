// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <limits>

#include "glider/hal/time.hpp"

namespace glider::hal {

// Latest GPS fix. Only fixes that passed the driver's checks (checksum, fix
// quality, plausible values) are ever `valid`; the firmware still checks age
// (`time_us`) because a fix stops updating when the antenna goes under.
struct GpsFix {
  double latitude_deg = 0.0;   // + north, WGS-84
  double longitude_deg = 0.0;  // + east
  int quality = 0;             // NMEA GGA fix quality: 0 none, 1 GPS, 2 DGPS, ...
  int satellites = 0;
  double hdop = 0.0;
  Micros time_us = 0;  // HAL clock time the fix was received
  bool valid = false;
  // The receiver's own UTC of the fix, seconds of the day (GGA hhmmss.ss;
  // NaN when not given): logged so a step of the system clock shows.
  double utc_time_of_day_s = std::numeric_limits<double>::quiet_NaN();
};

class GpsReceiver {
 public:
  virtual ~GpsReceiver() = default;
  // Non-blocking: returns the newest fix seen so far (or an invalid one).
  virtual GpsFix read() = 0;
};

}  // namespace glider::hal
