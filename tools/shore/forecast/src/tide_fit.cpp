// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/tide_fit.hpp"

#include "glider/fitting_core/intervals.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace glider::forecast {

double tide_fit_record_needed_s(const std::vector<std::string>& names) {
  double needed = 0.0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const double pi = tide_constituent_period_s(names[i]);
    needed = std::max(needed, pi);
    for (std::size_t j = i + 1; j < names.size(); ++j) {
      const double df = std::fabs(1.0 / pi - 1.0 / tide_constituent_period_s(names[j]));
      if (!(df > 0.0)) throw std::runtime_error("constituent " + names[i] + " is asked twice");
      needed = std::max(needed, 1.0 / df);
    }
  }
  return needed;
}

TideFit fit_tide(const std::vector<CurrentSample>& samples, const std::vector<std::string>& names,
                 double reference_utc_s) {
  if (names.empty()) throw std::runtime_error("no constituent asked");
  const double needed = tide_fit_record_needed_s(names);
  TideFit fit;
  fit.estimates = static_cast<int>(samples.size());
  if (!samples.empty()) {
    double first = samples.front().utc_s - 0.5 * samples.front().span_s, last = first;
    for (const CurrentSample& s : samples) {
      first = std::min(first, s.utc_s - 0.5 * s.span_s);
      last = std::max(last, s.utc_s + 0.5 * s.span_s);
    }
    fit.record_s = last - first;
  }
  std::string asked;
  for (const std::string& n : names) asked += (asked.empty() ? "" : ", ") + n;
  char text[400];
  if (fit.record_s < needed) {
    std::snprintf(text, sizeof text,
                  "the record (%d estimates over %.1f h) is too short to fit %s: it needs %.1f h (the Rayleigh "
                  "criterion: each constituent's period, 1 / |f1 - f2| for each pair)",
                  fit.estimates, fit.record_s / 3600.0, asked.c_str(), needed / 3600.0);
    throw std::runtime_error(text);
  }
  const auto k = static_cast<Eigen::Index>(names.size());
  const Eigen::Index p = 1 + 2 * k;
  const auto n = static_cast<Eigen::Index>(samples.size());
  if (n < p + 2) {
    std::snprintf(text, sizeof text, "%d estimates cannot fit %s with an interval: at least %d", fit.estimates,
                  asked.c_str(), static_cast<int>(p + 2));
    throw std::runtime_error(text);
  }
  std::vector<double> omega;
  for (const std::string& name : names) omega.push_back(2.0 * std::numbers::pi / tide_constituent_period_s(name));
  Eigen::MatrixXd x(n, p);
  Eigen::MatrixXd y(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    const CurrentSample& s = samples[static_cast<std::size_t>(i)];
    x(i, 0) = 1.0;
    for (Eigen::Index c = 0; c < k; ++c) {
      const double w = omega[static_cast<std::size_t>(c)];
      const double half = 0.5 * w * s.span_s;
      const double kept = std::fabs(half) < 1e-9 ? 1.0 : std::sin(half) / half;  // the segment's mean
      x(i, 1 + 2 * c) = kept * std::cos(w * (s.utc_s - reference_utc_s));
      x(i, 2 + 2 * c) = kept * std::sin(w * (s.utc_s - reference_utc_s));
    }
    y(i, 0) = s.east_m_s;
    y(i, 1) = s.north_m_s;
  }
  const Eigen::MatrixXd normal = x.transpose() * x;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-8)) {
    throw std::runtime_error("the estimates' times cannot tell " + asked +
                             " apart (the fit is singular: too few distinct phases of the tide)");
  }
  const Eigen::MatrixXd inverse = ldlt.solve(Eigen::MatrixXd::Identity(p, p));
  fit.t95 = fitting_core::t_quantile_975(static_cast<double>(n - p));  // the residual's degrees of freedom
  fit.table.reference_utc_s = reference_utc_s;
  for (Eigen::Index c = 0; c < k; ++c) {
    TideConstituent tc;
    tc.name = names[static_cast<std::size_t>(c)];
    tc.period_s = tide_constituent_period_s(tc.name);
    fit.table.constituents.push_back(tc);
  }
  for (int comp = 0; comp < 2; ++comp) {
    const Eigen::VectorXd b = ldlt.solve(x.transpose() * y.col(comp));
    const Eigen::VectorXd r = y.col(comp) - x * b;
    const double s2 = r.squaredNorm() / static_cast<double>(n - p);
    (comp == 0 ? fit.residual_east_m_s : fit.residual_north_m_s) = std::sqrt(r.squaredNorm() / static_cast<double>(n));
    (comp == 0 ? fit.table.mean_east_m_s : fit.table.mean_north_m_s) = b(0);
    for (Eigen::Index c = 0; c < k; ++c) {
      const double a = b(1 + 2 * c), s = b(2 + 2 * c);
      const double va = s2 * inverse(1 + 2 * c, 1 + 2 * c), vs = s2 * inverse(2 + 2 * c, 2 + 2 * c);
      const double cas = s2 * inverse(1 + 2 * c, 2 + 2 * c);
      const double amp = std::hypot(a, s);
      TideComponent& out = comp == 0 ? fit.table.constituents[static_cast<std::size_t>(c)].east
                                     : fit.table.constituents[static_cast<std::size_t>(c)].north;
      out.amplitude_m_s = amp;
      out.phase_deg = std::atan2(s, a) * 180.0 / std::numbers::pi;
      // Linearised: the amplitude's variance along (a, s), the phase's across it.
      const double amp2 = std::max(amp * amp, 1e-12);
      out.amplitude_sigma_m_s = std::sqrt(std::max(0.0, (a * a * va + s * s * vs + 2.0 * a * s * cas) / amp2));
      out.phase_sigma_deg =
          std::min(180.0, std::sqrt(std::max(0.0, (s * s * va + a * a * vs - 2.0 * a * s * cas) / (amp2 * amp2))) *
                              180.0 / std::numbers::pi);
    }
  }
  return fit;
}

}  // namespace glider::forecast
