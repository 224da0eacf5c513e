// SPDX-License-Identifier: Apache-2.0
// A 95 % interval the residual does not support (issue 26 item 4): a fit
// whose model output moves in steps of its parameter (a flight whose samples,
// branches or clamps change with it) gives a forward-difference Jacobian
// that is either far too steep (the tiny step crosses a jump) or exactly flat
// (it does not), and the covariance then collapses the interval to a few
// parts per million or to zero - as glider-diagnose did for a thermal
// expansion on a truth log. The fitting core's profile check must widen both
// to the profile the residual supports, and leave a sound Jacobian's alone.
// A fresh seed every run (printed; GLIDER_TEST_SEED=N replays it).
#include <CppUTest/TestHarness.h>

#include <Eigen/Dense>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "glider/fitting_core/effective_samples.hpp"
#include "glider/fitting_core/intervals.hpp"
#include "glider/fitting_core/profile_check.hpp"

namespace fc = glider::fitting_core;

namespace {

std::uint64_t test_seed() {
  if (const char* given = std::getenv("GLIDER_TEST_SEED"); given != nullptr && *given != '\0') {
    return std::strtoull(given, nullptr, 10);
  }
  return std::random_device{}();
}

// y = a x + white noise (sd 0.1), 400 samples; the model's slope moves in
// steps of `quantum` (0: smoothly).
struct SteppedLine {
  std::vector<double> x, y;
  double quantum = 0.0;
  double slope(double a) const { return quantum > 0.0 ? quantum * std::floor(a / quantum) : a; }
  std::vector<double> residuals(double a) const {
    std::vector<double> r(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) r[i] = slope(a) * x[i] - y[i];
    return r;
  }
  double rss(double a) const {
    double s = 0.0;
    for (double v : residuals(a)) s += v * v;
    return s;
  }
  // The forward difference glider-diagnose takes (forward_difference.hpp: h = sqrt(eps) |a|).
  Eigen::MatrixXd jacobian(double a) const {
    const double h = std::sqrt(std::numeric_limits<double>::epsilon()) * std::abs(a);
    const std::vector<double> r0 = residuals(a), r1 = residuals(a + h);
    Eigen::MatrixXd jac(static_cast<Eigen::Index>(x.size()), 1);
    for (std::size_t i = 0; i < x.size(); ++i) jac(static_cast<Eigen::Index>(i), 0) = (r1[i] - r0[i]) / h;
    return jac;
  }
};

SteppedLine draw(std::uint64_t seed, double quantum) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.1);
  SteppedLine line;
  line.quantum = quantum;
  for (int i = 0; i < 400; ++i) {
    line.x.push_back(u(rng));
    line.y.push_back(2.0 * line.x.back() + noise(rng));
  }
  return line;
}

// The least-squares slope (smooth model).
double fitted_slope(const SteppedLine& line) {
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < line.x.size(); ++i) sxy += line.x[i] * line.y[i], sxx += line.x[i] * line.x[i];
  return sxy / sxx;
}

struct Reading {
  double jacobian_half = 0.0;  // 1.96 sigma of the Jacobian's covariance
  double checked_half = 0.0;   // after the profile check
  double profile_half = 0.0;   // the smooth line's exact 95 % conditional profile half-width
};

Reading read(const SteppedLine& line, double a) {
  const std::vector<double> r = line.residuals(a);
  const std::vector<long> cluster(r.size(), 0);
  const fc::ParameterUncertainty uncertainty(line.jacobian(a), r, cluster, fc::IntervalRule::kLag1);
  Reading out;
  out.jacobian_half = fc::kZ95 * uncertainty.sigma(Eigen::Index{0});
  const double rss = line.rss(a);
  const double n_eff = std::max(fc::effective_sample_count(r, 0.0), 3.0);
  out.checked_half =
      fc::profile_checked_half_width(a, out.jacobian_half, rss, n_eff, 1, 1e-6, [&](double v) { return line.rss(v); });
  double sxx = 0.0;
  for (double v : line.x) sxx += v * v;
  out.profile_half = std::sqrt(3.84 * rss / (n_eff - 1.0) / sxx);
  return out;
}

}  // namespace

TEST_GROUP(ZeroWidthIntervals){};

// The difference step crosses a jump of the model: the column is ~3000x too
// steep and the interval collapses (the thermal-expansion case).
TEST(ZeroWidthIntervals, AJacobianAcrossAStepIsWidenedToTheProfile) {
  const std::uint64_t seed = test_seed();
  std::printf("\nzero-width: seed %" PRIu64 " (replay: GLIDER_TEST_SEED=%" PRIu64 ")\n", seed, seed);
  const double quantum = 1e-4;
  const SteppedLine line = draw(seed, quantum);
  // The fit point just below a step, within the forward difference's reach.
  const double a = quantum * std::ceil(fitted_slope(line) / quantum) - 1e-9;
  const Reading got = read(line, a);
  std::printf("across a step: Jacobian half %.3g, checked %.3g, profile %.3g\n", got.jacobian_half, got.checked_half,
              got.profile_half);
  CHECK_TEXT(got.jacobian_half < 1e-3 * got.profile_half, "the collapse is reproduced (else the test proves nothing)");
  CHECK(got.checked_half >= got.profile_half * (1.0 - 1e-3));  // the step's own 1e-4 may shift the profile slightly
  CHECK(got.checked_half <= 2.05 * got.profile_half);          // one doubling past it at most
}

// The difference step lands inside a flat of the model: the column is zero,
// the pseudo-inverse gives a zero variance and a zero-width interval.
TEST(ZeroWidthIntervals, AFlatJacobianIsWidenedToTheProfile) {
  const std::uint64_t seed = test_seed();
  std::printf("\nzero-width: seed %" PRIu64 " (replay: GLIDER_TEST_SEED=%" PRIu64 ")\n", seed, seed);
  const double quantum = 1e-4;
  const SteppedLine line = draw(seed, quantum);
  const double a = quantum * (std::floor(fitted_slope(line) / quantum) + 0.5);  // mid-step
  const Reading got = read(line, a);
  std::printf("flat: Jacobian half %.3g, checked %.3g, profile %.3g\n", got.jacobian_half, got.checked_half,
              got.profile_half);
  CHECK_TEXT(got.jacobian_half == 0.0, "the zero-width interval is reproduced");
  CHECK(got.checked_half >= got.profile_half * (1.0 - 1e-3));
  CHECK(got.checked_half <= 2.05 * got.profile_half);
}

// A sound Jacobian (a smooth model) is kept exactly: nothing moves.
TEST(ZeroWidthIntervals, ASoundJacobianIsKept) {
  const std::uint64_t seed = test_seed();
  std::printf("\nzero-width: seed %" PRIu64 " (replay: GLIDER_TEST_SEED=%" PRIu64 ")\n", seed, seed);
  const SteppedLine line = draw(seed, 0.0);
  const Reading got = read(line, fitted_slope(line));
  // Linear: the two agree (to 1.96^2 vs the profile threshold's 3.84).
  DOUBLES_EQUAL(got.profile_half, got.jacobian_half, 1e-3 * got.profile_half);
  DOUBLES_EQUAL(got.jacobian_half, got.checked_half, 0.0);
}
