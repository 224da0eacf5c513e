// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/course_straightness.hpp"

#include <algorithm>
#include <cmath>

#include "glider/circular_statistics/circular_statistics.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/forecast/from_glider.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;

std::vector<HeadingSample> logged_headings(const fs::path& glider_dir, double since_utc_s,
                                           std::vector<std::string>& notes) {
  std::vector<HeadingSample> out;
  for_each_from_glider_log(
      glider_dir, {"m_depth", "m_heading"}, "heading", notes, [&](const flightlog::FlightLog& log) {
        const flightlog::Column& t = log.time();
        const flightlog::Column& depth = log.column("m_depth");
        const flightlog::Column& heading = log.column("m_heading");
        for (std::size_t i = 0; i < t.size(); ++i) {
          if (!(t[i] >= since_utc_s) || !(depth[i] > kCourseMinDepthM) || !std::isfinite(heading[i])) continue;
          out.push_back({t[i], heading[i]});
        }
      });
  std::sort(out.begin(), out.end(),
            [](const HeadingSample& a, const HeadingSample& b) { return a.time_utc_s < b.time_utc_s; });
  return out;
}

double course_straightness(const std::vector<HeadingSample>& samples, double from_utc_s, double to_utc_s) {
  const double nan = std::nan("");
  if (!(to_utc_s > from_utc_s)) return nan;
  const auto first = std::lower_bound(samples.begin(), samples.end(), from_utc_s,
                                      [](const HeadingSample& s, double t) { return s.time_utc_s < t; });
  const auto last = std::upper_bound(samples.begin(), samples.end(), to_utc_s,
                                     [](double t, const HeadingSample& s) { return t < s.time_utc_s; });
  const std::ptrdiff_t n = last - first;
  if (n < kCourseMinSamples) return nan;
  circular_statistics::MeanResultant course;
  for (auto it = first; it != last; ++it) {
    // Half the time to each neighbour in the span, none across a gap.
    double weight = 0.0;
    if (it != first && it->time_utc_s - (it - 1)->time_utc_s <= kCourseMaxGapS)
      weight += 0.5 * (it->time_utc_s - (it - 1)->time_utc_s);
    if (it + 1 != last && (it + 1)->time_utc_s - it->time_utc_s <= kCourseMaxGapS)
      weight += 0.5 * ((it + 1)->time_utc_s - it->time_utc_s);
    course.add(it->heading_rad, weight);
  }
  if (!(course.total_weight() >= kCourseMinCover * (to_utc_s - from_utc_s))) return nan;
  return course.length();
}

}  // namespace glider::forecast
