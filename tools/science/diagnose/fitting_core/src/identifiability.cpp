// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/identifiability.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

namespace glider::fitting_core {

Complement::Complement(const Eigen::MatrixXd& columns)
    : q_(columns.cols() > 0 ? Eigen::MatrixXd(columns.householderQr().householderQ() *
                                              Eigen::MatrixXd::Identity(columns.rows(), columns.cols()))
                            : Eigen::MatrixXd(columns.rows(), 0)) {}

Eigen::VectorXd Complement::of(const Eigen::VectorXd& v) const { return v - q_ * (q_.transpose() * v); }

Eigen::VectorXd signature_column(const std::vector<double>& stepped, const std::vector<double>& base, double step) {
  const auto n = static_cast<Eigen::Index>(base.size());
  Eigen::VectorXd column(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double v = (stepped[static_cast<std::size_t>(i)] - base[static_cast<std::size_t>(i)]) / step;
    column[i] = std::isfinite(v) ? v : 0.0;
  }
  return column;
}

std::vector<ScreenedPair> pair_correlations(const EffectSet& chosen, const std::vector<int>& alternatives,
                                            const std::function<Eigen::VectorXd(int)>& signature) {
  std::vector<ScreenedPair> out;
  std::vector<Eigen::VectorXd> signatures;
  for (int e : chosen) signatures.push_back(signature(e));
  for (std::size_t j = 0; j < chosen.size(); ++j) {
    const Eigen::Index n = signatures[j].size();
    Eigen::MatrixXd others(n, static_cast<Eigen::Index>(chosen.size()) - 1);
    for (std::size_t k = 0, c = 0; k < chosen.size(); ++k) {
      if (k != j) others.col(static_cast<Eigen::Index>(c++)) = signatures[k];
    }
    const Complement complement(others);
    const Eigen::VectorXd a = complement.of(signatures[j]);
    for (int alternative : alternatives) {
      if (std::find(chosen.begin(), chosen.end(), alternative) != chosen.end()) continue;
      out.push_back({j, alternative, absolute_correlation(a, complement.of(signature(alternative)))});
    }
  }
  return out;
}

std::vector<ScreenedPair> screened(const std::vector<ScreenedPair>& all, double screen) {
  std::vector<ScreenedPair> out;
  for (const ScreenedPair& pair : all) {
    if (pair.correlation >= screen) out.push_back(pair);  // NaN: no signature, nothing to judge
  }
  return out;
}

std::vector<ScreenedPair> screen_pairs(const EffectSet& chosen, const std::vector<int>& alternatives,
                                       const std::function<Eigen::VectorXd(int)>& signature, double screen) {
  return screened(pair_correlations(chosen, alternatives, signature), screen);
}

double absolute_correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const double norms = a.norm() * b.norm();
  if (!(norms > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return std::abs(a.dot(b)) / norms;
}

}  // namespace glider::fitting_core
