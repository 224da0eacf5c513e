// SPDX-License-Identifier: Apache-2.0
#pragma once
// Positions: Slocum's NMEA ddmm.mmm angles, decimal degrees, and a local
// east/north plane in metres. Glider legs are tens of km, where the flat-earth
// (equirectangular) approximation about a reference point is good to metres
// per 10 km; it is also what the Slocum flight computer uses for m_x_lmc/m_y_lmc.
#include <cmath>

#include "glider/units.hpp"

namespace glider::fw {

// NMEA ddmm.mmm (5418.9674 = 54 deg 18.9674 min) to decimal degrees; the sign
// is kept (south and west are negative in Slocum files).
inline double nmea_to_degrees(double ddmm) {
  const double magnitude = std::fabs(ddmm);
  const double degrees = std::floor(magnitude / 100.0);
  const double minutes = magnitude - 100.0 * degrees;
  return std::copysign(degrees + minutes / 60.0, ddmm);
}

inline double degrees_to_nmea(double degrees) {
  const double magnitude = std::fabs(degrees);
  const double whole = std::floor(magnitude);
  return std::copysign(100.0 * whole + 60.0 * (magnitude - whole), degrees);
}

// WGS-84 mean radius for the local plane; the ellipsoid's flattening changes
// local distances by < 0.7 %, well inside the DR and GPS errors at issue.
constexpr double kEarthRadiusM = 6371000.0;

struct LatLon {
  double lat_deg = 0.0;
  double lon_deg = 0.0;
};

struct EastNorth {
  double east_m = 0.0;
  double north_m = 0.0;
};

// A local tangent plane about an origin.
class LocalFrame {
 public:
  LocalFrame() = default;
  explicit LocalFrame(LatLon origin) : origin_(origin), cos_lat_(std::cos(deg_to_rad(origin.lat_deg))) {}

  EastNorth to_local(LatLon p) const {
    return {deg_to_rad(p.lon_deg - origin_.lon_deg) * kEarthRadiusM * cos_lat_,
            deg_to_rad(p.lat_deg - origin_.lat_deg) * kEarthRadiusM};
  }
  LatLon to_global(EastNorth p) const {
    return {origin_.lat_deg + rad_to_deg(p.north_m / kEarthRadiusM),
            origin_.lon_deg + rad_to_deg(p.east_m / (kEarthRadiusM * cos_lat_))};
  }
  const LatLon& origin() const { return origin_; }

 private:
  LatLon origin_{};
  double cos_lat_ = 1.0;
};

// Heading of the straight line from `from` to `to`: 0 north, clockwise, [0, 2 pi).
inline double bearing_rad(EastNorth from, EastNorth to) {
  const double b = std::atan2(to.east_m - from.east_m, to.north_m - from.north_m);
  return b < 0.0 ? b + 2.0 * std::numbers::pi : b;
}

inline double distance_m(EastNorth a, EastNorth b) { return std::hypot(b.east_m - a.east_m, b.north_m - a.north_m); }

// Smallest signed angle a - b, in (-pi, pi].
inline double wrap_pi(double angle) {
  const double two_pi = 2.0 * std::numbers::pi;
  double a = std::fmod(angle + std::numbers::pi, two_pi);
  if (a < 0.0) a += two_pi;
  return a - std::numbers::pi;
}

}  // namespace glider::fw
