// SPDX-License-Identifier: Apache-2.0
// Yo tops at the surface inside a dive (surface_touches.hpp): the speed term
// does not measure the glider's speed from the DR of a dive whose DR
// restarted at fixes there (comet-2016). Synthetic depth profiles.
#include <CppUTest/TestHarness.h>

#include <vector>

#include "glider/forecast/surface_touches.hpp"

namespace fc = glider::forecast;

namespace {

// A dive from t = 0: `yos` yos between 40 m and `top_m`, 0.15 m/s, 4 s rows,
// from and back to the surface (0.2 m).
std::vector<fc::DepthSample> dive(int yos, double top_m) {
  std::vector<fc::DepthSample> out;
  double t = 0.0, depth = 0.2;
  const auto go = [&](double to) {
    const double step = (to > depth ? 0.6 : -0.6);
    while ((step > 0.0 && depth < to) || (step < 0.0 && depth > to)) {
      out.push_back({t, depth});
      t += 4.0;
      depth += step;
    }
    depth = to;
  };
  for (int i = 0; i < yos; ++i) {
    go(40.0);
    go(i + 1 < yos ? top_m : 0.2);
  }
  out.push_back({t, depth});
  return out;
}

}  // namespace

TEST_GROUP(ForecastSurfaceTouches){};

TEST(ForecastSurfaceTouches, EveryYoTopAtTheSurfaceInsideTheDiveIsCounted) {
  const std::vector<fc::DepthSample> d = dive(4, 0.3);  // comet-2016: 8 half yos, tops at 0-0.4 m
  CHECK_EQUAL(3, fc::surface_touches(d, -1.0, d.back().time_utc_s + 1.0, 1.0));
}

TEST(ForecastSurfaceTouches, TopsBelowTheSurfaceAndTheDivesOwnEndsAreNot) {
  const std::vector<fc::DepthSample> deep_tops = dive(4, 5.0);
  CHECK_EQUAL(0, fc::surface_touches(deep_tops, -1.0, deep_tops.back().time_utc_s + 1.0, 1.0));
  const std::vector<fc::DepthSample> one = dive(1, 0.3);
  CHECK_EQUAL(0, fc::surface_touches(one, -1.0, one.back().time_utc_s + 1.0, 1.0));
}

TEST(ForecastSurfaceTouches, OnlyTheTopsBetweenTheTwoTimes) {
  const std::vector<fc::DepthSample> d = dive(4, 0.3);
  const double end = d.back().time_utc_s;
  CHECK_EQUAL(1, fc::surface_touches(d, -1.0, 0.4 * end, 1.0));
  CHECK_EQUAL(0, fc::surface_touches(d, 0.1 * end, 0.2 * end, 1.0));
}
