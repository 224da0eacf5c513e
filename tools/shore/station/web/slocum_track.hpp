// SPDX-License-Identifier: Apache-2.0
#pragma once
// The dead-reckoned track in the glider's received files: the shore's
// NAME.sbd.csv conversions (m_present_time, m_lat/m_lon = DR, m_gps_lat/m_gps_lon
// = fixes, all Slocum DDMM). Each file is read once (cached by size and mtime).
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace glider::shore::web {

struct TrackPoint {
  double t = 0.0;  // m_present_time (the glider's clock)
  double lat = 0.0, lon = 0.0;
  bool gps = false;  // a fix, else a DR position
};

// The DR error at a surfacing: the DR position just before the first fix
// after a stretch of DR rows, against that fix.
struct DrError {
  double t = 0.0;  // the fix's m_present_time
  double error_m = 0.0;
  double lat = 0.0, lon = 0.0;  // the fix
};

class TrackCache {
 public:
  // Points of every *.sbd.csv / *.tbd.csv in `folder`, by file name (= time) order.
  std::vector<TrackPoint> read(const std::filesystem::path& folder);

 private:
  struct Entry {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type mtime;
    std::vector<TrackPoint> points;
  };
  std::map<std::string, Entry> files_;
};

std::vector<DrError> dr_errors(const std::vector<TrackPoint>& points);
double distance_m(double lat1, double lon1, double lat2, double lon2);

}  // namespace glider::shore::web
