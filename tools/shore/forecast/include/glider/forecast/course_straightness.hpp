// SPDX-License-Identifier: Apache-2.0
#pragma once
// How straight a dive's course was, from the headings the glider sent home:
// the speed term (speed_term.hpp) measures the glider's speed through the
// water from its dead reckoning's net track over a dive, and a course that
// turned covers less net ground than it glides. The comet's dive 154 (nsb3,
// 1.9 h at 242 deg, then 0.8 h at 305 deg, the heading swinging +-25 deg
// about the command) made good 0.224 m/s through the water while its
// navigator counted m_speed 0.265 m/s all the way: its course's straightness
// 0.84 is that ratio (docs/forecast.md, "The speed through the water").
#include <filesystem>
#include <string>
#include <vector>

namespace glider::forecast {

struct HeadingSample {
  double time_utc_s = 0.0;
  double heading_rad = 0.0;
};

// The samples of m_heading taken deeper than kCourseMinDepthM (under way, not
// drifting at the surface) since `since_utc_s`, in time order, from
// GLIDER_DIR/from-glider/*.csv (glider-convert's conversions of what the
// glider sent home). A file without m_depth and m_heading is passed over; one
// that names them but does not read is named in `notes` and skipped.
inline constexpr double kCourseMinDepthM = 2.0;
std::vector<HeadingSample> logged_headings(const std::filesystem::path& glider_dir, double since_utc_s,
                                           std::vector<std::string>& notes);

// The time-weighted mean resultant length of the headings between two times
// (1: one heading all the way; cos(d/2) for two equal legs d apart): each
// sample weighs half the time to its neighbours, a gap over kCourseMaxGapS
// weighs none. NaN when the samples cover less than kCourseMinCover of the
// span or number fewer than kCourseMinSamples: then the net track says
// nothing of the course.
inline constexpr double kCourseMaxGapS = 60.0;
inline constexpr double kCourseMinCover = 0.5;
inline constexpr int kCourseMinSamples = 20;
double course_straightness(const std::vector<HeadingSample>& samples, double from_utc_s, double to_utc_s);

}  // namespace glider::forecast
