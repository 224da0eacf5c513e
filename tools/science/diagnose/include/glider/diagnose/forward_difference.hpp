// SPDX-License-Identifier: Apache-2.0
#pragma once
// A Levenberg-Marquardt functor's Jacobian by forward differences: Eigen's
// NumericalDiff in its Forward mode (the same steps, so the same bits),
// except that f(x) is not evaluated again when x was the functor's last
// evaluation - as it is every time Eigen's Levenberg-Marquardt asks for the
// Jacobian (it has just evaluated, and accepted, x). Where one evaluation
// flies the flight model through a whole log, that saves one flight of the
// k + 1 a Jacobian of k parameters costs.
#include <Eigen/Core>
#include <cmath>
#include <limits>

namespace glider::diagnose {

template <class Functor>
class ForwardDifference : public Functor {
 public:
  explicit ForwardDifference(const Functor& f) : Functor(f) {}

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    const int status = Functor::operator()(x, f);
    remember(x, f);
    return status;
  }

  // f at x computed by the caller (e.g. in one flight with other samples).
  void remember(const Eigen::VectorXd& x, const Eigen::VectorXd& f) const {
    last_x_ = x;
    last_f_ = f;
  }

  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
    if (last_x_.size() != x.size() || last_x_ != x) {
      Eigen::VectorXd f(Functor::values());
      (*this)(x, f);
    }
    const double eps = std::sqrt(std::numeric_limits<double>::epsilon());  // NumericalDiff's, epsfcn = 0
    Eigen::VectorXd shifted = x;
    Eigen::VectorXd f_shifted(Functor::values());
    for (Eigen::Index j = 0; j < x.size(); ++j) {
      double h = eps * std::abs(x[j]);
      if (h == 0.0) h = eps;
      shifted[j] += h;
      Functor::operator()(shifted, f_shifted);
      shifted[j] = x[j];
      jac.col(j) = (f_shifted - last_f_) / h;
    }
    // NumericalDiff's count of evaluations, so that the optimiser's budget
    // (maxfev) ends a fit where it always did.
    return static_cast<int>(x.size()) + 1;
  }

 private:
  mutable Eigen::VectorXd last_x_, last_f_;
};

}  // namespace glider::diagnose
