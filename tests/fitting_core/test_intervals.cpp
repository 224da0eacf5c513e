// SPDX-License-Identifier: Apache-2.0
// The 95 % intervals: their coverage of a known truth over many seeded
// draws (the noise serially correlated, or shared within clusters), against
// what a rule that ignores the correlation would cover; Student-t intervals
// at printed quantiles.
#include <CppUTest/TestHarness.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "draws.hpp"
#include "glider/fitting_core/intervals.hpp"

namespace fc = glider::fitting_core;

namespace {

// A mean fitted to `y`: the Jacobian of the residual (mean - y) is a column of ones.
struct MeanFit {
  Eigen::MatrixXd jac;
  std::vector<double> r;
  double mean = 0.0;
};
MeanFit fit_mean(const std::vector<double>& y) {
  MeanFit f;
  for (double v : y) f.mean += v / static_cast<double>(y.size());
  f.jac = Eigen::MatrixXd::Ones(static_cast<Eigen::Index>(y.size()), 1);
  for (double v : y) f.r.push_back(f.mean - v);
  return f;
}

}  // namespace

TEST_GROUP(FittingCoreIntervals) { std::mt19937_64 rng{20261128}; };

TEST(FittingCoreIntervals, CorrelatedNoiseIntervalsCoverTheTruth) {
  const int trials = 400;
  int covered = 0, covered_if_independent = 0;
  for (int t = 0; t < trials; ++t) {
    const MeanFit f = fit_mean(fitting_core_test::ar1(rng, 400, 0.8, 1.0));  // truth: 0
    const double sigma = std::sqrt(fc::noise_covariance(f.jac, f.r)(0, 0));
    if (std::abs(f.mean) <= fc::kZ95 * sigma) ++covered;
    double rss = 0.0;
    for (double v : f.r) rss += v * v;
    if (std::abs(f.mean) <= fc::kZ95 * std::sqrt(rss / 399.0 / 400.0)) ++covered_if_independent;
  }
  const double coverage = static_cast<double>(covered) / trials;
  CHECK_TEXT(coverage >= 0.90 && coverage <= 0.99, ("coverage " + std::to_string(coverage)).c_str());
  // Counting every sample as independent covers far less: the rule matters.
  CHECK(static_cast<double>(covered_if_independent) / trials < 0.75);
}

TEST(FittingCoreIntervals, ClusterRobustIntervalsCoverSharedErrors) {
  const int trials = 400, clusters = 8, per_cluster = 50;
  int covered = 0, covered_by_noise_rule = 0;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> y;
    std::vector<long> cluster;
    for (int g = 0; g < clusters; ++g) {
      const double shared = fitting_core_test::normal(rng);  // one model error per glide
      for (int i = 0; i < per_cluster; ++i) {
        y.push_back(shared + 0.3 * fitting_core_test::normal(rng));
        cluster.push_back(g);
      }
    }
    const MeanFit f = fit_mean(y);
    double t_over_normal = 0.0;
    const double sigma = std::sqrt(fc::cluster_covariance(f.jac, f.r, cluster, t_over_normal)(0, 0));
    DOUBLES_EQUAL(2.3646 / 1.96, t_over_normal, 1e-4);  // Student-t, 7 degrees of freedom
    if (std::abs(f.mean) <= fc::kZ95 * t_over_normal * sigma) ++covered;
    if (std::abs(f.mean) <= fc::kZ95 * std::sqrt(fc::noise_covariance(f.jac, f.r)(0, 0))) ++covered_by_noise_rule;
  }
  const double coverage = static_cast<double>(covered) / trials;
  CHECK_TEXT(coverage >= 0.90 && coverage <= 0.99, ("coverage " + std::to_string(coverage)).c_str());
  // The lag-1 rule sees errors shared over a whole glide only in part.
  CHECK(covered_by_noise_rule < covered);
}

TEST(FittingCoreIntervals, OneClusterHasNoSpreadToSee) {
  const MeanFit f = fit_mean({1.0, 2.0, 3.0});
  double t_over_normal = 0.0;
  const std::vector<long> one{4, 4, 4};
  CHECK(std::isinf(fc::cluster_covariance(f.jac, f.r, one, t_over_normal)(0, 0)));
}

TEST(FittingCoreIntervals, StudentIntervals) {
  DOUBLES_EQUAL(2.7764, fc::t_quantile_975(4.0), 1e-4);
  const fc::Estimate e = fc::t_interval(10.0, 2.0, 4.0);
  DOUBLES_EQUAL(10.0 - 2.0 * 2.7764, e.low, 1e-3);
  DOUBLES_EQUAL(10.0 + 2.0 * 2.7764, e.high, 1e-3);
  const std::vector<double> five{1.0, 2.0, 3.0, 4.0, 5.0};
  const fc::Estimate m = fc::mean_with_interval(five);  // se = sqrt(2.5 / 5)
  DOUBLES_EQUAL(3.0, m.value, 1e-12);
  DOUBLES_EQUAL(3.0 - 2.7764 * std::sqrt(0.5), m.low, 1e-3);
}

TEST(FittingCoreIntervals, TheGlideRuleIsTheWiderOfLag1AndClusters) {
  std::vector<double> y;
  std::vector<long> cluster;
  for (int g = 0; g < 6; ++g) {
    const double shared = fitting_core_test::normal(rng);
    for (int i = 0; i < 40; ++i) {
      y.push_back(shared + 0.3 * fitting_core_test::normal(rng));
      cluster.push_back(g);
    }
  }
  const MeanFit f = fit_mean(y);
  const double lag1 = std::sqrt(fc::noise_covariance(f.jac, f.r)(0, 0));
  double t_over_normal = 0.0;
  const double clustered = std::sqrt(fc::cluster_covariance(f.jac, f.r, cluster, t_over_normal)(0, 0));
  const fc::ParameterUncertainty by_lag1(f.jac, f.r, cluster, fc::IntervalRule::kLag1);
  const fc::ParameterUncertainty by_glides(f.jac, f.r, cluster, fc::IntervalRule::kGlides);
  DOUBLES_EQUAL(lag1, by_lag1.sigma(0), 1e-12);
  DOUBLES_EQUAL(std::max(lag1, t_over_normal * clustered), by_glides.sigma(0), 1e-12);
  CHECK(by_glides.sigma(0) > by_lag1.sigma(0));  // errors shared by a glide: the clusters see them
  // The same rule for a mean: the glides' interval, wider than lag-1's.
  const fc::Estimate m1 = fc::mean_with_rule(y, cluster, fc::IntervalRule::kLag1);
  const fc::Estimate mg = fc::mean_with_rule(y, cluster, fc::IntervalRule::kGlides);
  DOUBLES_EQUAL(f.mean, mg.value, 1e-12);
  DOUBLES_EQUAL(fc::kZ95 * by_glides.sigma(0), 0.5 * (mg.high - mg.low), 1e-9);
  CHECK(mg.high - mg.low > m1.high - m1.low);
  CHECK(fc::cluster_of(fc::IntervalRule::kGlides, 3, 2) != fc::cluster_of(fc::IntervalRule::kGlides, 3, 4));
  CHECK(fc::cluster_of(fc::IntervalRule::kYos, 3, 2) == fc::cluster_of(fc::IntervalRule::kYos, 3, 4));
}

TEST(FittingCoreIntervals, AReplicateWidensByTheBirgeRatioAndNeverNarrows) {
  DOUBLES_EQUAL(1.0, fc::replicated_sigma(1.0, 0.0, 1.0, 1.0), 1e-12);  // ratio 1/sqrt(2): kept
  DOUBLES_EQUAL(4.0 / std::sqrt(2.0), fc::replicated_sigma(1.0, 0.0, 1.0, 4.0), 1e-12);
  // |1 - -4| / hypot(2, 4) = 1.118: 2 -> 2.236.
  DOUBLES_EQUAL(2.0 * 5.0 / std::hypot(2.0, 4.0), fc::replicated_sigma(2.0, 1.0, 4.0, -4.0), 1e-12);
  DOUBLES_EQUAL(1.5, fc::replicated_sigma(1.5, 0.0, 1.0, std::nan("")), 0.0);  // a failed replicate: kept
  DOUBLES_EQUAL(1.5, fc::replicated_sigma(1.5, 0.0, std::numeric_limits<double>::infinity(), 3.0), 0.0);
}

// A mean fitted to one half of the data (the training yos) and replicated on
// the other (the held-out yos), each half with its own model-form error (a
// term the fitted model lacks, different in each half's water): the lag-1
// interval sees only the noise and misses; the replicate's Birge ratio sees
// the halves disagree. Without a model error the replicate costs little width.
TEST(FittingCoreIntervals, AHeldOutReplicateCoversAModelFormError) {
  const int trials = 400;
  for (const double model_error : {0.0, 1.0}) {
    int covered_lag1 = 0, covered_replicated = 0;
    std::vector<double> widening;
    for (int t = 0; t < trials; ++t) {
      double value[2], sigma[2];
      for (int half = 0; half < 2; ++half) {
        // 300 samples of AR(1) noise, phi 0.8: the mean's sigma about 0.17.
        std::vector<double> y = fitting_core_test::ar1(rng, 300, 0.8, 1.0);
        const double shared = model_error * 0.17 * fitting_core_test::normal(rng);  // truth: 0
        for (double& v : y) v += shared;
        const MeanFit f = fit_mean(y);
        value[half] = f.mean;
        sigma[half] = std::sqrt(fc::noise_covariance(f.jac, f.r)(0, 0));
      }
      const double replicated = fc::replicated_sigma(sigma[0], value[0], sigma[1], value[1]);
      CHECK(replicated >= sigma[0]);
      if (std::abs(value[0]) <= fc::kZ95 * sigma[0]) ++covered_lag1;
      if (std::abs(value[0]) <= fc::kZ95 * replicated) ++covered_replicated;
      widening.push_back(replicated / sigma[0]);
    }
    std::sort(widening.begin(), widening.end());
    const double lag1 = static_cast<double>(covered_lag1) / trials;
    const double replicated = static_cast<double>(covered_replicated) / trials;
    const std::string what = "model error " + std::to_string(model_error) + ": lag-1 " + std::to_string(lag1) +
                             ", replicated " + std::to_string(replicated) + ", median widening " +
                             std::to_string(widening[trials / 2]);
    if (model_error == 0.0) {
      CHECK_TEXT(lag1 >= 0.90 && replicated <= 0.995, what.c_str());
      CHECK_TEXT(widening[trials / 2] < 1.05, what.c_str());  // most intervals unchanged
    } else {
      CHECK_TEXT(lag1 < 0.88, what.c_str());  // the model-only interval misses
      CHECK_TEXT(replicated >= 0.90, what.c_str());
    }
  }
}

// The equal-weight mixture's central 95 %, against answers worked out by
// hand: one reading is its own interval; two far apart each give their 95 %
// one-sided quantile (the other carries half the weight); a wide reading
// beside a narrow one gives the wide one's 90 % (the narrow one's mass all
// inside), short of the union's end; a point beside a reading likewise.
TEST(FittingCoreIntervals, TheMixtureOfReadingsWeighedAlike) {
  const std::vector<double> one_mean{2.0}, one_sigma{0.5};
  const fc::Estimate one = fc::mixture_interval(one_mean, one_sigma);
  DOUBLES_EQUAL(2.0 - 1.959964 * 0.5, one.low, 1e-6);
  DOUBLES_EQUAL(2.0 + 1.959964 * 0.5, one.high, 1e-6);
  const std::vector<double> far_means{-10.0, 10.0}, far_sigmas{1.0, 1.0};
  const fc::Estimate far = fc::mixture_interval(far_means, far_sigmas);
  DOUBLES_EQUAL(10.0 + 1.644854, far.high, 1e-6);  // Phi^-1(0.95)
  DOUBLES_EQUAL(-10.0 - 1.644854, far.low, 1e-6);
  DOUBLES_EQUAL(0.0, far.value, 1e-12);
  const std::vector<double> nested_means{0.0, 0.0}, nested_sigmas{1.0, 3.0};
  const fc::Estimate nested = fc::mixture_interval(nested_means, nested_sigmas);
  DOUBLES_EQUAL(3.0 * 1.644854, nested.high, 2e-3);  // Phi(4.93) = 1 - 4e-7 for the narrow one
  CHECK(nested.high < 3.0 * 1.959964);               // the union's end
  const std::vector<double> point_means{0.0, 0.0}, point_sigmas{0.0, 1.0};
  DOUBLES_EQUAL(1.644854, fc::mixture_interval(point_means, point_sigmas).high, 1e-6);
}
