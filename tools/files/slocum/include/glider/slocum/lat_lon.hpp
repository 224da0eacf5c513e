// SPDX-License-Identifier: Apache-2.0
#pragma once
// Slocum stores positions as NMEA ddmm.mmmm (signed) in a fixed set of
// sensors; 69696969 marks an invalid fix. These are dbdreader's rules, so the
// decoded arrays match its output bit for bit.
#include <string_view>

namespace glider::slocum {

// The sensors dbdreader treats as positions (its LATLON_PARAMS).
bool is_lat_lon_sensor(std::string_view name);
// A latitude sensor must stay within +-9000 (90 deg), a longitude within
// +-18000; anything else (69696969, NaN) is not a position.
bool is_valid_nmea(std::string_view name, double nmea);
// ddmm.mmmm -> decimal degrees, with dbdreader's arithmetic.
double nmea_to_decimal(double nmea);

}  // namespace glider::slocum
