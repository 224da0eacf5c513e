// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/identifiability.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>

namespace glider::fitting_core {

Complement::Complement(const Eigen::MatrixXd& columns)
    : q_(columns.cols() > 0 ? Eigen::MatrixXd(columns.householderQr().householderQ() *
                                              Eigen::MatrixXd::Identity(columns.rows(), columns.cols()))
                            : Eigen::MatrixXd(columns.rows(), 0)) {}

Eigen::VectorXd Complement::of(const Eigen::VectorXd& v) const { return v - q_ * (q_.transpose() * v); }

double absolute_correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double norms = a.norm() * b.norm();
  if (!(norms > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::abs(a.dot(b)) / norms;
}

}  // namespace glider::fitting_core
