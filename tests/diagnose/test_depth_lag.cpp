// SPDX-License-Identifier: Apache-2.0
// The diagnosis's depth_lag: the model's depth as a late sensor reads it.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "glider/diagnose/depth_lag.hpp"

using glider::diagnose::delay_depth;

TEST_GROUP(DiagnoseDepthLag){};

TEST(DiagnoseDepthLag, ReadsTheDepthLagSecondsEarlier) {
  // A turn: a parabola sampled every 1.5 s; the late sensor reads it lag
  // seconds earlier (linear between samples, exact at sample times).
  std::vector<double> t, z;
  for (int k = 0; k < 20; ++k) {
    t.push_back(1.466e9 + 1.5 * k);  // an epoch clock, as the logs'
    z.push_back(30.0 - 0.01 * (1.5 * k - 15.0) * (1.5 * k - 15.0));
  }
  std::vector<double> late = z;
  delay_depth(t, late, 3.0);  // two samples
  for (std::size_t k = 2; k < z.size(); ++k) DOUBLES_EQUAL(z[k - 2], late[k], 1e-12);
  late = z;
  delay_depth(t, late, 0.75);  // half a sample: between the two
  for (std::size_t k = 1; k < z.size(); ++k) DOUBLES_EQUAL(0.5 * (z[k - 1] + z[k]), late[k], 1e-12);
  // Before the first sample: along the first interval.
  DOUBLES_EQUAL(z[0] - 0.5 * (z[1] - z[0]), late[0], 1e-12);
}

TEST(DiagnoseDepthLag, ResolvesTheOptimisersStepOnAnEpochClock) {
  // A Jacobian step of 1.5e-8 s must move the depth although an epoch time
  // itself resolves only 2e-7 s: the lag is applied to time differences.
  std::vector<double> t{1.466e9, 1.466e9 + 1.0, 1.466e9 + 2.0, 1.466e9 + 3.0};
  std::vector<double> z{10.0, 10.1, 10.3, 10.6}, a = z, b = z;
  delay_depth(t, a, 1.0);
  delay_depth(t, b, 1.0 + 1.5e-8);
  CHECK(b[3] < a[3]);
  DOUBLES_EQUAL(-1.5e-8 * 0.2, b[3] - a[3], 1e-12);
}

TEST(DiagnoseDepthLag, NoLagLeavesTheDepth) {
  std::vector<double> t{0.0, 1.0, 2.0}, z{1.0, 2.0, 4.0}, same = z;
  delay_depth(t, same, 0.0);
  for (std::size_t k = 0; k < z.size(); ++k) DOUBLES_EQUAL(z[k], same[k], 0.0);
}
