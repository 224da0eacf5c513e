// SPDX-License-Identifier: Apache-2.0
#pragma once
// Yo tops at the surface inside a dive, from the depths the glider sent home:
// a Slocum that comes up to the surface between its calls (comet-2016's yo
// tops at 0-0.4 m) takes GPS positions there and restarts its dead reckoning
// from them, so its DR position at the call is not the track from the fix it
// dived from: the speed term's (DR - fix) / time then counts the whole dive's
// water track over its last leg (comet-2016: 0.37 m/s, 1.37 x the model's).
// Such dives are named and not measured (speed_term.cpp).
#include <filesystem>
#include <string>
#include <vector>

namespace glider::forecast {

struct DepthSample {
  double time_utc_s = 0.0;
  double depth_m = 0.0;
};

// m_depth since `since_utc_s` from GLIDER_DIR/from-glider/*.csv in time
// order (a file without m_depth passed over; an unreadable one named in
// `notes`).
std::vector<DepthSample> logged_depths(const std::filesystem::path& glider_dir, double since_utc_s,
                                       std::vector<std::string>& notes);

// The times the glider came up shallower than `surface_m` from deeper than
// kTouchFromDepthM and went down past kTouchFromDepthM again, all strictly
// between `from_utc_s` and `to_utc_s` (the dive's start and its surfacing:
// neither counts).
inline constexpr double kTouchFromDepthM = 3.0;
int surface_touches(const std::vector<DepthSample>& samples, double from_utc_s, double to_utc_s, double surface_m);

}  // namespace glider::forecast
