// SPDX-License-Identifier: Apache-2.0
#include "mission_waypoints.hpp"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "utc_time.hpp"

namespace glider::shore::web {

double ddmm_to_degrees(double ddmm) {
  const double magnitude = std::fabs(ddmm);
  const double degrees = std::floor(magnitude / 100.0);
  const double value = degrees + (magnitude - 100.0 * degrees) / 60.0;
  return ddmm < 0 ? -value : value;
}

std::vector<std::pair<double, double>> read_waypoints(const std::filesystem::path& ma_file) {
  std::vector<std::pair<double, double>> points;
  std::ifstream in(ma_file);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    if (line.find("<start:waypoints>") != std::string::npos) {
      inside = true;
      continue;
    }
    if (line.find("<end:waypoints>") != std::string::npos) break;
    if (!inside) continue;
    std::istringstream words(line);
    double lon = kUnknown, lat = kUnknown;
    if (!(words >> lon >> lat)) continue;
    lat = ddmm_to_degrees(lat);
    lon = ddmm_to_degrees(lon);
    if (std::isfinite(lat) && std::isfinite(lon) && std::fabs(lat) <= 90.0 && std::fabs(lon) <= 180.0) {
      points.emplace_back(lat, lon);
    }
  }
  return points;
}

}  // namespace glider::shore::web
