// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/intervals.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "glider/fitting_core/effective_samples.hpp"

namespace glider::fitting_core {

Eigen::MatrixXd noise_covariance(const Eigen::MatrixXd& jac, std::span<const double> r) {
  const auto k = static_cast<double>(jac.cols());
  const Eigen::MatrixXd bread = (jac.transpose() * jac).completeOrthogonalDecomposition().pseudoInverse();
  double rss = 0.0;
  for (double v : r) rss += v * v;
  const double n_eff = std::max(effective_sample_count(r, 0.0), k + 2.0);
  return bread * (rss / (n_eff - k));  // RSS / (n_eff - k) = s^2 n / n_eff: inflated for correlation
}

Eigen::MatrixXd cluster_covariance(const Eigen::MatrixXd& jac, std::span<const double> r, std::span<const long> cluster,
                                   double& t_over_normal) {
  const auto k = static_cast<double>(jac.cols());
  const auto n = static_cast<double>(r.size());
  const Eigen::MatrixXd bread = (jac.transpose() * jac).completeOrthogonalDecomposition().pseudoInverse();
  t_over_normal = 1.0;
  std::map<long, Eigen::VectorXd> score;  // per cluster: J_g' r_g
  for (std::size_t i = 0; i < r.size(); ++i) {
    auto [it, added] = score.try_emplace(cluster[i], Eigen::VectorXd::Zero(jac.cols()));
    it->second += jac.row(static_cast<Eigen::Index>(i)).transpose() * r[i];
  }
  const auto g = static_cast<double>(score.size());
  if (g < 2.0) return bread * std::numeric_limits<double>::infinity();  // one cluster: no spread to see
  Eigen::MatrixXd meat = Eigen::MatrixXd::Zero(jac.cols(), jac.cols());
  for (const auto& [id, s] : score) meat += s * s.transpose();
  const double small_sample = g / (g - 1.0) * (n - 1.0) / std::max(1.0, n - k);
  t_over_normal = t_quantile_975(g - 1.0) / kZ95;
  return bread * meat * bread * small_sample;
}

ParameterUncertainty::ParameterUncertainty(const Eigen::MatrixXd& jac, std::span<const double> r,
                                           std::span<const long> cluster, IntervalRule rule)
    : lag1_(noise_covariance(jac, r)) {
  if (rule == IntervalRule::kLag1) return;
  clustered_ = cluster_covariance(jac, r, cluster, t_over_normal_);
  has_clustered_ = true;
}

double ParameterUncertainty::sigma(const Eigen::VectorXd& w) const {
  const double lag1 = std::sqrt(std::max(w.dot(lag1_ * w), 0.0));
  if (!has_clustered_) return lag1;
  return std::max(lag1, t_over_normal_ * std::sqrt(std::max(w.dot(clustered_ * w), 0.0)));
}

double ParameterUncertainty::sigma(Eigen::Index j) const {
  return sigma(Eigen::VectorXd(Eigen::VectorXd::Unit(lag1_.rows(), j)));
}

long cluster_of(IntervalRule rule, int yo, int phase) {
  switch (rule) {
    case IntervalRule::kLag1:
      return 0;
    case IntervalRule::kGlides:
      return 8L * yo + phase;
    case IntervalRule::kYos:
      return yo;
  }
  return 0;
}

Estimate mean_with_rule(std::span<const double> x, std::span<const long> cluster, IntervalRule rule) {
  const auto n = static_cast<double>(x.size());
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= n;
  double var = 0.0;
  for (double v : x) var += (v - mean) * (v - mean);
  const double var_of_mean_lag1 = var / (n - 1.0) / std::max(2.0, effective_sample_count(x, mean));
  if (rule == IntervalRule::kLag1) {
    const double half = kZ95 * std::sqrt(var_of_mean_lag1);
    return {mean, mean - half, mean + half};
  }
  const Eigen::MatrixXd ones = Eigen::MatrixXd::Ones(static_cast<Eigen::Index>(x.size()), 1);
  std::vector<double> r(x.begin(), x.end());
  for (double& v : r) v = mean - v;  // the residual of the fitted mean
  const double lag1_half = kZ95 * std::sqrt(var_of_mean_lag1);
  double t_over_normal = 1.0;
  const double variance = cluster_covariance(ones, r, cluster, t_over_normal)(0, 0);
  const double half = std::max(lag1_half, kZ95 * t_over_normal * std::sqrt(variance));  // the wider (IntervalRule)
  return {mean, mean - half, mean + half};
}

double replicated_sigma(double sigma_a, double a, double sigma_b, double b) {
  const double joint = std::hypot(sigma_a, sigma_b);
  if (!std::isfinite(joint) || !std::isfinite(a) || !std::isfinite(b) || !(joint > 0.0)) return sigma_a;
  return sigma_a * std::max(1.0, std::abs(a - b) / joint);
}

double t_quantile_975(double degrees_of_freedom) {
  return boost::math::quantile(boost::math::students_t_distribution<double>(degrees_of_freedom), 0.975);
}

Estimate t_interval(double value, double standard_error, double degrees_of_freedom) {
  const double half = t_quantile_975(degrees_of_freedom) * standard_error;
  return {value, value - half, value + half};
}

Estimate mixture_interval(std::span<const double> means, std::span<const double> sigmas) {
  const std::size_t n = std::min(means.size(), sigmas.size());
  double low = std::numeric_limits<double>::infinity(), high = -low, mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    low = std::min(low, means[i] - 10.0 * sigmas[i]);
    high = std::max(high, means[i] + 10.0 * sigmas[i]);
    mean += means[i] / static_cast<double>(n);
  }
  const auto cdf = [&](double x) {
    double p = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      p += sigmas[i] > 0.0 ? 0.5 * std::erfc((means[i] - x) / (sigmas[i] * std::sqrt(2.0))) : (x >= means[i]);
    }
    return p / static_cast<double>(n);
  };
  const auto quantile = [&](double q) {  // bisection: the cdf is monotone
    double a = low, b = high;
    for (int i = 0; i < 200 && b - a > 1e-14 * std::max(std::abs(a), std::abs(b)); ++i) {
      const double mid = 0.5 * (a + b);
      (cdf(mid) < q ? a : b) = mid;
    }
    return 0.5 * (a + b);
  };
  return {mean, quantile(0.025), quantile(0.975)};
}

Estimate mean_with_interval(std::span<const double> values) {
  const std::size_t n = values.size();
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(n);
  double squares = 0.0;
  for (double v : values) squares += (v - mean) * (v - mean);
  const double se = std::sqrt(squares / static_cast<double>(n - 1) / static_cast<double>(n));
  return t_interval(mean, se, static_cast<double>(n - 1));
}

}  // namespace glider::fitting_core
