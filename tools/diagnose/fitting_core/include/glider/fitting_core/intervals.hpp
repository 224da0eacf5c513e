// SPDX-License-Identifier: Apache-2.0
#pragma once
// 95 % intervals, one rule each, for every plane and the deployment view:
// the covariance of a least-squares fit's parameters from its Jacobian, with
// the noise counted over the effective sample count (effective_samples.hpp)
// or cluster-robust (each glide or yo a cluster), and Student-t intervals of
// a few independent estimates (a deployment's segments).
#include <Eigen/Core>
#include <span>

namespace glider::fitting_core {

// The normal distribution's two-sided 95 % quantile, as every plane has used it.
inline constexpr double kZ95 = 1.96;

struct Interval {
  double low = 0.0, high = 0.0;
};

// An estimate with its 95 % interval.
struct Estimate {
  double value = 0.0, low = 0.0, high = 0.0;
};

// Covariance of the fitted parameters from the Jacobian `jac` (one row per
// residual `r`): (J'J)^+ RSS / (n_eff - k), the noise variance over the
// effective sample count (n_eff at least k + 2) - the residuals' serial
// correlation inflates it by n / n_eff.
Eigen::MatrixXd noise_covariance(const Eigen::MatrixXd& jac, std::span<const double> r);

// The cluster-robust (sandwich) covariance (J'J)^+ [sum_g (J_g' r_g)(J_g' r_g)'] (J'J)^+
// with the small-sample factor G/(G-1) (n-1)/(n-k), `cluster[i]` naming row
// i's cluster (a glide or a yo); `t_over_normal` the Student-t quantile on
// G - 1 degrees of freedom over 1.96. One cluster: infinite.
Eigen::MatrixXd cluster_covariance(const Eigen::MatrixXd& jac, std::span<const double> r, std::span<const long> cluster,
                                   double& t_over_normal);

// The two-sided 95 % quantile of Student's t.
double t_quantile_975(double degrees_of_freedom);

// value +- t(dof) standard_error.
Estimate t_interval(double value, double standard_error, double degrees_of_freedom);

// The mean of independent estimates of one value and its 95 % Student-t
// interval from their scatter (n - 1 degrees of freedom); needs n >= 2.
Estimate mean_with_interval(std::span<const double> values);

}  // namespace glider::fitting_core
