// SPDX-License-Identifier: Apache-2.0
#pragma once
// The waypoints of a Slocum goto .ma file (`<start:waypoints>` ... `<end:waypoints>`,
// one "LON LAT" a line in signed DDMM.MMMM), as decimal degrees, for the map.
#include <filesystem>
#include <utility>
#include <vector>

namespace glider::shore::web {

// {lat_deg, lon_deg} pairs; empty when the file has no waypoint block or cannot be read.
// A line that is not two finite numbers on the globe is skipped (the vehicle judges the file, not the map).
std::vector<std::pair<double, double>> read_waypoints(const std::filesystem::path& ma_file);

// Slocum's signed DDMM.MMMM as decimal degrees.
double ddmm_to_degrees(double ddmm);

}  // namespace glider::shore::web
