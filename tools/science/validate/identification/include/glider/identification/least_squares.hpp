// SPDX-License-Identifier: Apache-2.0
#pragma once
// Ordinary linear least squares with the textbook parameter covariance
// sigma^2 (X^T X)^-1, sigma^2 = RSS / (n - p). The regressors are taken as
// exact (here they are angles of attack that themselves carry some noise:
// the standard errors are then slightly optimistic).
#include <Eigen/Core>

namespace glider::identification {

struct LinearFit {
  bool ok = false;  // enough rows and full column rank
  Eigen::VectorXd coefficients;
  Eigen::VectorXd standard_errors;  // NaN without degrees of freedom (n == p)
  Eigen::MatrixXd covariance;       // NaN without degrees of freedom
  double residual_sd = 0.0;         // sqrt(RSS / dof), NaN when dof == 0
  int dof = 0;                      // rows minus coefficients
};

LinearFit least_squares(const Eigen::MatrixXd& design, const Eigen::VectorXd& observed);

}  // namespace glider::identification
