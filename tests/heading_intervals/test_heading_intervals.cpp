// SPDX-License-Identifier: Apache-2.0
// The heading plane's smooth effects (the fin's authority, the roll offset,
// the yaw's time constant, the autopilot's gains) take the fitting core's
// profile check as the vertical plane's do (issue 26 items 4-5, one rule
// written once): a residual that is not smooth at the forward difference's
// scale (a replay whose samples, clamps or cycle timing move with the
// parameter) gives a Jacobian column far too steep and an interval far too
// narrow; the check widens it to the conditional profile the residual
// supports, and leaves a sound Jacobian's alone. Through
// select_heading_effects, the heading plane's one fit. A fresh seed every
// run (printed; GLIDER_TEST_SEED=N replays it).
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <span>
#include <vector>

#include "glider/diagnose/heading_fit.hpp"
#include "glider/fitting_core/delay_search.hpp"
#include "glider/fitting_core/effective_samples.hpp"

namespace gd = glider::diagnose;
namespace fc = glider::fitting_core;

namespace {

std::uint64_t test_seed() {
  if (const char* given = std::getenv("GLIDER_TEST_SEED"); given != nullptr && *given != '\0') {
    return std::strtoull(given, nullptr, 10);
  }
  return std::random_device{}();
}

// y = truth x + white noise (sd 0.1), 400 samples; the model's slope is the
// effect's value plus, within `zone` of the truth, a ripple of amplitude
// `ripple` and period 2 pi 1e-6: the RSS hardly moves with it, but the
// forward difference (a few 1e-9 of the value) reads its slope, up to
// ripple / 1e-6 times the true one.
struct RippledLine {
  gd::HeadingEffect effect;
  double truth = 0.0, ripple = 0.0, zone = 0.05;
  std::vector<double> x, y;
  double slope(double a) const { return std::abs(a - truth) < zone ? a + ripple * std::sin(a / 1e-6) : a; }
  void residuals(const gd::HeadingValues& v, std::span<const std::size_t> which, std::vector<double>& out) const {
    out.resize(which.size());
    const double s = slope(gd::at(v, effect));
    for (std::size_t k = 0; k < which.size(); ++k) out[k] = s * x[which[k]] - y[which[k]];
  }
};

RippledLine draw(std::uint64_t seed, gd::HeadingEffect effect, double truth, double ripple) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.1);
  RippledLine line{effect, truth, ripple, 0.05, {}, {}};
  for (int i = 0; i < 400; ++i) {
    line.x.push_back(u(rng));
    line.y.push_back(truth * line.x.back() + noise(rng));
  }
  return line;
}

struct Reading {
  double value = 0.0, low = 0.0, high = 0.0;
  double profile_low = 0.0, profile_high = 0.0;  // the conditional profile's 95 % crossings (the residual's own)
};

Reading fit(const RippledLine& line, const gd::HeadingValues& nominal) {
  gd::LinkSamples samples;
  for (std::size_t i = 0; i < line.x.size(); ++i) {
    samples.all.push_back(i);
    (i % 2 == 0 ? samples.train : samples.heldout).push_back(i);
  }
  gd::HeadingSelectOptions options;
  options.fit_only = {line.effect};
  options.select = false;
  const gd::HeadingResiduals residuals = [&](const gd::HeadingValues& v, std::span<const std::size_t> w,
                                             std::vector<double>& o) { line.residuals(v, w, o); };
  const gd::LinkFit got =
      gd::select_heading_effects(gd::HeadingLink::kVehicle, {line.effect}, nominal, residuals, samples, options);
  Reading out;
  if (got.findings.size() != 1) return out;
  out.value = got.findings[0].value;
  out.low = got.findings[0].ci95_low;
  out.high = got.findings[0].ci95_high;
  auto rss_at = [&](double a) {
    gd::HeadingValues v = got.values;
    gd::at(v, line.effect) = a;
    std::vector<double> r;
    line.residuals(v, samples.train, r);
    double s = 0.0;
    for (double e : r) s += e * e;
    return s;
  };
  std::vector<double> r;
  line.residuals(got.values, samples.train, r);
  const double rss = rss_at(out.value);
  const double limit = fc::profile_threshold(rss, std::max(fc::effective_sample_count(r), 3.0), 1);
  double d = 0.0;
  while (rss_at(out.value - d) < limit && d < 10.0) d += 1e-4;
  out.profile_low = out.value - d;
  d = 0.0;
  while (rss_at(out.value + d) < limit && d < 10.0) d += 1e-4;
  out.profile_high = out.value + d;
  return out;
}

gd::HeadingValues nominal_values() {
  gd::HeadingValues v{};
  gd::at(v, gd::HeadingEffect::kFinEffectiveness) = 1.0;
  gd::at(v, gd::HeadingEffect::kYawTimeConstant) = 2.0;
  gd::at(v, gd::HeadingEffect::kAutopilotGain) = 1.5;
  return v;
}

void check(gd::HeadingEffect effect, double truth, std::uint64_t seed) {
  const RippledLine line = draw(seed, effect, truth, 1e-3);
  const Reading got = fit(line, nominal_values());
  std::printf("%s truth %.3f: %.4f [%.4f, %.4f], profile [%.4f, %.4f]\n", gd::info(effect).id, truth, got.value,
              got.low, got.high, got.profile_low, got.profile_high);
  CHECK_TEXT(std::abs(got.value - truth) < 0.05, "the fit reaches the rippled zone (else the test proves nothing)");
  // Never narrower than the residual's own profile (its 1e-4 scan step and
  // the ripple's 1e-3 aside), at most one doubling past it.
  CHECK(got.low <= got.profile_low + 2e-3);
  CHECK(got.high >= got.profile_high - 2e-3);
  CHECK(got.high - got.low <= 2.1 * (got.profile_high - got.profile_low) + 4e-3);
}

}  // namespace

TEST_GROUP(HeadingIntervals){};

// The ripple's slope in the Jacobian: without the check the interval is
// ~100x narrower than the profile (fin 1.3: a half-width of ~2e-4 for ~0.02).
TEST(HeadingIntervals, AJacobianOnARippleIsWidenedToTheProfile) {
  const std::uint64_t seed = test_seed();
  std::printf("\nheading intervals: seed %" PRIu64 " (replay: GLIDER_TEST_SEED=%" PRIu64 ")\n", seed, seed);
  check(gd::HeadingEffect::kFinEffectiveness, 1.3, seed);
  check(gd::HeadingEffect::kRollOffset, 0.06, seed + 1);
  check(gd::HeadingEffect::kAutopilotGain, 2.2, seed + 2);
}

// A smooth residual: the Jacobian's interval is the profile's already and
// stays as it was (a linear fit's marginal interval is its profile).
TEST(HeadingIntervals, ASoundJacobianIsKept) {
  const std::uint64_t seed = test_seed();
  std::printf("\nheading intervals: seed %" PRIu64 " (replay: GLIDER_TEST_SEED=%" PRIu64 ")\n", seed, seed);
  const RippledLine line = draw(seed, gd::HeadingEffect::kFinEffectiveness, 1.3, 0.0);
  const Reading got = fit(line, nominal_values());
  std::printf("smooth: %.4f [%.4f, %.4f], profile [%.4f, %.4f]\n", got.value, got.low, got.high, got.profile_low,
              got.profile_high);
  DOUBLES_EQUAL(got.profile_high - got.profile_low, got.high - got.low, 0.15 * (got.profile_high - got.profile_low));
}
