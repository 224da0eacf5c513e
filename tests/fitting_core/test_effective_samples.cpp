// SPDX-License-Identifier: Apache-2.0
// The effective sample count of serially correlated residuals: an AR(1)'s
// n (1 - phi) / (1 + phi), white noise's n.
#include <CppUTest/TestHarness.h>

#include <vector>

#include "draws.hpp"
#include "glider/fitting_core/effective_samples.hpp"

using glider::fitting_core::effective_sample_count;

TEST_GROUP(FittingCoreEffectiveSamples) { std::mt19937_64 rng{20261127}; };

TEST(FittingCoreEffectiveSamples, WhiteNoiseCountsEverySample) {
  const std::vector<double> x = fitting_core_test::ar1(rng, 20000, 0.0, 1.0);
  DOUBLES_EQUAL(20000.0, effective_sample_count(x), 20000.0 * 0.03);
}

TEST(FittingCoreEffectiveSamples, CorrelatedNoiseCountsFewer) {
  const std::vector<double> x = fitting_core_test::ar1(rng, 20000, 0.9, 1.0);
  const double expected = 20000.0 * 0.1 / 1.9;  // 1053
  DOUBLES_EQUAL(expected, effective_sample_count(x), 0.15 * expected);
}

TEST(FittingCoreEffectiveSamples, AboutTheGivenMean) {
  std::vector<double> x = fitting_core_test::ar1(rng, 20000, 0.0, 1.0);
  for (double& v : x) v += 5.0;
  // About 0 the offset is shared by every sample: r1 = 25 / 26, n / 51 left.
  DOUBLES_EQUAL(20000.0 / 51.0, effective_sample_count(x, 0.0), 0.05 * 20000.0 / 51.0);
  DOUBLES_EQUAL(20000.0, effective_sample_count(x, 5.0), 20000.0 * 0.03);
}

TEST(FittingCoreEffectiveSamples, ConstantOrEmptyIsItsLength) {
  const std::vector<double> zeros(10, 0.0);
  DOUBLES_EQUAL(10.0, effective_sample_count(zeros), 0.0);
  DOUBLES_EQUAL(0.0, effective_sample_count(std::vector<double>{}), 0.0);
}
