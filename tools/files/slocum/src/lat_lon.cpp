// SPDX-License-Identifier: Apache-2.0
#include "glider/slocum/lat_lon.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace glider::slocum {
namespace {

constexpr std::array<std::string_view, 28> kLatLonSensors = {"m_lat",
                                                             "m_lon",
                                                             "c_wpt_lat",
                                                             "c_wpt_lon",
                                                             "x_last_wpt_lat",
                                                             "x_last_wpt_lon",
                                                             "m_gps_lat",
                                                             "m_gps_lon",
                                                             "u_lat_goto_l99",
                                                             "u_lon_goto_l99",
                                                             "m_last_gps_lat_1",
                                                             "m_last_gps_lon_1",
                                                             "m_last_gps_lat_2",
                                                             "m_last_gps_lon_2",
                                                             "m_last_gps_lat_3",
                                                             "m_last_gps_lon_3",
                                                             "m_last_gps_lat_4",
                                                             "m_last_gps_lon_4",
                                                             "m_gps_ignored_lat",
                                                             "m_gps_ignored_lon",
                                                             "m_gps_invalid_lat",
                                                             "m_gps_invalid_lon",
                                                             "m_gps_toofar_lat",
                                                             "m_gps_toofar_lon",
                                                             "xs_lat",
                                                             "xs_lon",
                                                             "s_ini_lat",
                                                             "s_ini_lon"};

}  // namespace

bool is_lat_lon_sensor(std::string_view name) {
  return std::find(kLatLonSensors.begin(), kLatLonSensors.end(), name) != kLatLonSensors.end();
}

bool is_valid_nmea(std::string_view name, double nmea) {
  const double limit = name.find("lat") != std::string_view::npos ? 9000.0 : 18000.0;
  return nmea >= -limit && nmea <= limit;
}

double nmea_to_decimal(double nmea) {
  // numpy: sign(x) * (floor(|x|/100) + (|x| - floor(|x|/100)*100)/60), in this order.
  const double sign = nmea > 0.0 ? 1.0 : (nmea < 0.0 ? -1.0 : 0.0);
  const double magnitude = std::fabs(nmea);
  const double degrees = std::floor(magnitude / 100.0);
  const double minutes = magnitude - degrees * 100.0;
  return (degrees + minutes / 60.0) * sign;
}

}  // namespace glider::slocum
