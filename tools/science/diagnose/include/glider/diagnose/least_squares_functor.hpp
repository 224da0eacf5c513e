// SPDX-License-Identifier: Apache-2.0
#pragma once
// The types Eigen's Levenberg-Marquardt (and NumericalDiff) ask of a functor
// of dynamic size: the diagnosis's fits (both planes) derive from this and add
// inputs(), values() and operator().
#include <Eigen/Core>

namespace glider::diagnose {

struct LeastSquaresFunctor {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };
};

}  // namespace glider::diagnose
