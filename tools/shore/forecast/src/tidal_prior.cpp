// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/tidal_prior.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace glider::forecast {
namespace {

constexpr double kOmega = 2.0 * std::numbers::pi / kM2PeriodS;

// A harmonic averaged over a span keeps sinc(omega span / 2) of its amplitude.
double kept(double span_s) {
  const double x = 0.5 * kOmega * span_s;
  return std::fabs(x) < 1e-9 ? 1.0 : std::sin(x) / x;
}

// Covariance of two segment means (middles t, spans s) under the prior: the
// mean's variance plus the tide's, cos(omega lag) of a random phase.
double covariance(double t1, double s1, double t2, double s2, const TidalPrior& p) {
  return p.mean_sigma_m_s * p.mean_sigma_m_s +
         p.m2_sigma_m_s * p.m2_sigma_m_s * std::cos(kOmega * (t1 - t2)) * kept(s1) * kept(s2);
}

}  // namespace

CurrentEstimate predict_with_prior(const std::vector<CurrentSample>& all, double from_utc_s, double to_utc_s,
                                   const TidalPrior& prior) {
  std::vector<CurrentSample> samples;
  for (const CurrentSample& s : all) {
    if (s.utc_s > from_utc_s - 86400.0 && s.utc_s <= from_utc_s) samples.push_back(s);
  }
  const double t_w = 0.5 * (from_utc_s + to_utc_s), s_w = std::max(0.0, to_utc_s - from_utc_s);
  const double prior_var = covariance(t_w, s_w, t_w, s_w, prior);
  CurrentEstimate e;
  e.method = "tidal prior";
  e.samples = static_cast<int>(samples.size());
  double var = prior_var;
  if (!samples.empty()) {
    const auto n = static_cast<Eigen::Index>(samples.size());
    Eigen::MatrixXd k(n, n);
    Eigen::VectorXd k_w(n), y_e(n), y_n(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      const CurrentSample& a = samples[static_cast<std::size_t>(i)];
      for (Eigen::Index j = 0; j < n; ++j) {
        const CurrentSample& b = samples[static_cast<std::size_t>(j)];
        k(i, j) = covariance(a.utc_s, a.span_s, b.utc_s, b.span_s, prior);
      }
      k(i, i) += prior.estimate_sigma_m_s * prior.estimate_sigma_m_s;
      k_w(i) = covariance(t_w, s_w, a.utc_s, a.span_s, prior);
      y_e(i) = a.east_m_s;
      y_n(i) = a.north_m_s;
    }
    // The noise on the diagonal keeps k positive definite.
    const Eigen::LLT<Eigen::MatrixXd> llt(k);
    if (llt.info() == Eigen::Success) {
      const Eigen::VectorXd weights = llt.solve(k_w);
      e.east_m_s = weights.dot(y_e);
      e.north_m_s = weights.dot(y_n);
      var = prior_var - weights.dot(k_w);
    }
  }
  e.sigma_east_m_s = e.sigma_north_m_s = std::sqrt(std::max(var, 0.0));
  return e;
}

double persistence_prior_variance(const CurrentSample& last, double from_utc_s, double to_utc_s,
                                  const TidalPrior& prior) {
  const double t_w = 0.5 * (from_utc_s + to_utc_s), s_w = std::max(0.0, to_utc_s - from_utc_s);
  // Var(W - S) = Var W + Var S - 2 Cov(W, S), S carrying the estimate's own error.
  return covariance(t_w, s_w, t_w, s_w, prior) + covariance(last.utc_s, last.span_s, last.utc_s, last.span_s, prior) +
         prior.estimate_sigma_m_s * prior.estimate_sigma_m_s -
         2.0 * covariance(t_w, s_w, last.utc_s, last.span_s, prior);
}

}  // namespace glider::forecast
