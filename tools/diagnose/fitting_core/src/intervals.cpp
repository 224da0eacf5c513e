// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/intervals.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <map>

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

double t_quantile_975(double degrees_of_freedom) {
  return boost::math::quantile(boost::math::students_t_distribution<double>(degrees_of_freedom), 0.975);
}

Estimate t_interval(double value, double standard_error, double degrees_of_freedom) {
  const double half = t_quantile_975(degrees_of_freedom) * standard_error;
  return {value, value - half, value + half};
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
