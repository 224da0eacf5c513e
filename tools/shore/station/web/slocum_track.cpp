// SPDX-License-Identifier: Apache-2.0
#include "slocum_track.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "mission_waypoints.hpp"

namespace glider::shore::web {
namespace fs = std::filesystem;
namespace {

bool ends_with(const std::string& text, const std::string& tail) {
  return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

bool number(const std::vector<std::string>& cells, int column, double& value) {
  if (column < 0 || static_cast<std::size_t>(column) >= cells.size() || cells[column].empty()) return false;
  char* end = nullptr;
  value = std::strtod(cells[column].c_str(), &end);
  return end != cells[column].c_str() && *end == '\0' && std::isfinite(value);
}

bool position(const std::vector<std::string>& cells, int lat_column, int lon_column, double& lat, double& lon) {
  if (!number(cells, lat_column, lat) || !number(cells, lon_column, lon)) return false;
  lat = ddmm_to_degrees(lat);
  lon = ddmm_to_degrees(lon);
  return std::fabs(lat) <= 90.0 && std::fabs(lon) <= 180.0;
}

std::vector<TrackPoint> read_csv(const fs::path& file) {
  std::vector<TrackPoint> points;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
  }
  const std::vector<std::string> header = split(line);
  auto column = [&](const char* name) {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  };
  const int t_col = column("m_present_time"), lat_col = column("m_lat"), lon_col = column("m_lon"),
            gps_lat_col = column("m_gps_lat"), gps_lon_col = column("m_gps_lon");
  if (t_col < 0) return points;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split(line);
    TrackPoint p;
    if (!number(cells, t_col, p.t)) continue;
    if (position(cells, gps_lat_col, gps_lon_col, p.lat, p.lon)) {
      p.gps = true;
      points.push_back(p);
    } else if (position(cells, lat_col, lon_col, p.lat, p.lon)) {
      points.push_back(p);
    }
  }
  return points;
}

}  // namespace

double distance_m(double lat1, double lon1, double lat2, double lon2) {
  constexpr double k = M_PI / 180.0;
  const double x = (lon2 - lon1) * k * std::cos(0.5 * (lat1 + lat2) * k);
  return 6371000.0 * std::hypot(x, (lat2 - lat1) * k);
}

std::vector<TrackPoint> TrackCache::read(const fs::path& folder) {
  std::vector<std::string> names;
  std::error_code error;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name[0] != '.' && (ends_with(name, ".sbd.csv") || ends_with(name, ".tbd.csv"))) names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  std::vector<TrackPoint> all;
  for (const std::string& name : names) {
    const fs::path path = folder / name;
    const std::uintmax_t size = fs::file_size(path, error);
    if (error) continue;
    const fs::file_time_type mtime = fs::last_write_time(path, error);
    if (error) continue;
    Entry& entry = files_[name];
    if (entry.size != size || entry.mtime != mtime) entry = Entry{size, mtime, read_csv(path)};
    all.insert(all.end(), entry.points.begin(), entry.points.end());
  }
  return all;  // file name order is time order (Slocum names count missions and segments up)
}

std::vector<DrError> dr_errors(const std::vector<TrackPoint>& points) {
  std::vector<DrError> errors;
  const TrackPoint* last_dr = nullptr;
  int dr_rows = 0;
  for (const TrackPoint& p : points) {
    if (!p.gps) {
      last_dr = &p;
      ++dr_rows;
      continue;
    }
    // A fix after a dive (10+ DR rows since the last fix): the DR's error there.
    if (last_dr != nullptr && dr_rows >= 10) {
      errors.push_back({p.t, distance_m(last_dr->lat, last_dr->lon, p.lat, p.lon), p.lat, p.lon});
    }
    dr_rows = 0;
    last_dr = nullptr;
  }
  return errors;
}

}  // namespace glider::shore::web
