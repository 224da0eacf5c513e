// SPDX-License-Identifier: Apache-2.0
#include "glider/identification/least_squares.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace glider::identification {

LinearFit least_squares(const Eigen::MatrixXd& design, const Eigen::VectorXd& observed) {
  LinearFit fit;
  const auto rows = design.rows();
  const auto cols = design.cols();
  if (cols == 0 || rows < cols || observed.size() != rows) return fit;
  // Column-pivoting QR: solves without forming X^T X and reports the rank.
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < cols) return fit;
  fit.ok = true;
  fit.coefficients = qr.solve(observed);
  fit.dof = static_cast<int>(rows - cols);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (fit.dof == 0) {
    fit.residual_sd = nan;
    fit.covariance = Eigen::MatrixXd::Constant(cols, cols, nan);
    fit.standard_errors = Eigen::VectorXd::Constant(cols, nan);
    return fit;
  }
  const double rss = (design * fit.coefficients - observed).squaredNorm();
  const double variance = rss / fit.dof;
  fit.residual_sd = std::sqrt(variance);
  // (X^T X)^-1 from the same QR: X P = Q R  =>  (X^T X)^-1 = P R^-1 R^-T P^T.
  const Eigen::MatrixXd r = qr.matrixR().topLeftCorner(cols, cols).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd r_inv = r.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(cols, cols));
  const Eigen::MatrixXd permuted = r_inv * r_inv.transpose();
  const auto& p = qr.colsPermutation();
  fit.covariance = variance * (p * permuted * p.transpose());
  fit.standard_errors = fit.covariance.diagonal().cwiseSqrt();
  return fit;
}

}  // namespace glider::identification
