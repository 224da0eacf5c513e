// SPDX-License-Identifier: Apache-2.0
#pragma once
// How well a log separates two candidate effects, before either is chosen:
// their signatures (the change of the fitted residuals for a small step of
// each) with the other findings' signatures projected out, and the
// correlation of what is left. A high correlation means the two move the
// data alike here; the held-out yos then decide (selection.hpp's
// indistinguishable): told apart, or ambiguous with both readings stated.
#include <Eigen/Core>

namespace glider::fitting_core {

// Projects vectors onto the complement of a set of columns (the other
// findings' signatures): what a signature adds beyond them.
class Complement {
 public:
  explicit Complement(const Eigen::MatrixXd& columns);
  Eigen::VectorXd of(const Eigen::VectorXd& v) const;

 private:
  Eigen::MatrixXd q_;  // orthonormal basis of the columns
};

// |a . b| / (|a| |b|); NaN when either is zero.
double absolute_correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

}  // namespace glider::fitting_core
