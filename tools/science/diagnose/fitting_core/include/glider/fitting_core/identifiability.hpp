// SPDX-License-Identifier: Apache-2.0
#pragma once
// How well a log separates two candidate effects, before either is chosen:
// their signatures (the change of the fitted residuals for a small step of
// each) with the other findings' signatures projected out, and the
// correlation of what is left. A high correlation means the two move the
// data alike here; the held-out yos then decide (selection.hpp's
// indistinguishable): told apart, or ambiguous with both readings stated.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "glider/fitting_core/stepwise.hpp"

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

// An effect's signature: the change of the residuals `stepped` from `base`
// per unit of `step` (a sample a model cannot predict changes nothing).
Eigen::VectorXd signature_column(const std::vector<double>& stepped, const std::vector<double>& base, double step);

// A finding (`chosen[finding]`) and an alternative to judge it against.
struct ScreenedPair {
  std::size_t finding = 0;
  int alternative = 0;
  double correlation = 0.0;
};

// Every finding of `chosen` against every effect of `alternatives` not
// chosen: the correlation of their signatures once the other findings'
// signatures are projected out of both (NaN where either is zero). The
// screen below keeps the high ones; a plane states the rest too, so a pair
// not judged says why (its correlation under the screen), never silently.
std::vector<ScreenedPair> pair_correlations(const EffectSet& chosen, const std::vector<int>& alternatives,
                                            const std::function<Eigen::VectorXd(int)>& signature);

// The pairs of `all` (pair_correlations) that correlate at least `screen`.
std::vector<ScreenedPair> screened(const std::vector<ScreenedPair>& all, double screen);

// Every finding of `chosen` against every effect of `alternatives` not
// chosen whose signatures (`signature(effect)`) correlate at least `screen`
// once the other findings' signatures are projected out of both: the pairs
// the data may not separate, for the plane to fit the alternative in the
// finding's place and judge (selection.hpp's indistinguishable).
std::vector<ScreenedPair> screen_pairs(const EffectSet& chosen, const std::vector<int>& alternatives,
                                       const std::function<Eigen::VectorXd(int)>& signature, double screen);

}  // namespace glider::fitting_core
