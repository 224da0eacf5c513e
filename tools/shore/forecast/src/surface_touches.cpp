// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/surface_touches.hpp"

#include <algorithm>
#include <cmath>

#include "glider/flightlog/flight_log.hpp"
#include "glider/forecast/from_glider.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;

std::vector<DepthSample> logged_depths(const fs::path& glider_dir, double since_utc_s,
                                       std::vector<std::string>& notes) {
  std::vector<DepthSample> out;
  for_each_from_glider_log(glider_dir, {"m_depth"}, "depth", notes, [&](const flightlog::FlightLog& log) {
    const flightlog::Column& t = log.time();
    const flightlog::Column& depth = log.column("m_depth");
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] >= since_utc_s && std::isfinite(depth[i])) out.push_back({t[i], depth[i]});
    }
  });
  std::sort(out.begin(), out.end(),
            [](const DepthSample& a, const DepthSample& b) { return a.time_utc_s < b.time_utc_s; });
  return out;
}

int surface_touches(const std::vector<DepthSample>& samples, double from_utc_s, double to_utc_s, double surface_m) {
  int touches = 0;
  bool deep = false;     // been below kTouchFromDepthM since the last touch (or the dive's start)
  bool touched = false;  // came up shallower than surface_m after being deep
  for (const DepthSample& s : samples) {
    if (!(s.time_utc_s > from_utc_s)) continue;
    if (!(s.time_utc_s < to_utc_s)) break;
    if (s.depth_m > kTouchFromDepthM) {
      if (touched) ++touches;  // down again: that top was inside the dive
      touched = false;
      deep = true;
    } else if (deep && s.depth_m < surface_m) {
      touched = true;
      deep = false;
    }
  }
  return touches;
}

}  // namespace glider::forecast
