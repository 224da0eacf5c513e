// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/current_estimate.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "glider/forecast/tidal_prior.hpp"

namespace glider::forecast {
namespace {

// The glider's per-segment estimate scatters by this much even in steady
// water (DR speed error, the fix's noise over a short segment): the floor of
// every sigma. It is the prior's estimate noise (0.02 m/s by default); in
// evidence mode the noise the estimates favour (tidal_prior.hpp): a 0.02
// floor made the SIL's 95 % ellipses hold the truth at 0.1-0.4 of their size.
constexpr double kSigmaFloorMS = 0.02;
constexpr double kNoHistorySigmaMS = 0.25;

struct Fit {
  double value = 0.0;
  double sigma = 0.0;
  bool ok = false;
};

// Weighted least squares of y = X b; returns the mean of X_eval b over the
// evaluation rows and its 1-sigma (parameter covariance from the residuals,
// plus the residual scatter itself: the next segment's own deviation).
Fit least_squares(const Eigen::MatrixXd& x, const Eigen::VectorXd& y, const Eigen::VectorXd& w,
                  const Eigen::RowVectorXd& x_eval, double floor) {
  const Eigen::Index n = x.rows(), p = x.cols();
  if (n <= p) return {};
  const Eigen::MatrixXd xw = w.asDiagonal() * x;
  const Eigen::MatrixXd normal = x.transpose() * xw;
  Eigen::LDLT<Eigen::MatrixXd> ldlt(normal);
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-10)) return {};
  const Eigen::VectorXd b = ldlt.solve(xw.transpose() * y);
  const Eigen::VectorXd r = y - x * b;
  const double wsum = w.sum();
  const double s2 = (r.array().square() * w.array()).sum() / wsum * static_cast<double>(n) / static_cast<double>(n - p);
  const Eigen::MatrixXd cov = ldlt.solve(Eigen::MatrixXd::Identity(p, p)) * s2 * wsum / static_cast<double>(n);
  Fit f;
  f.value = x_eval * b;
  const double param_var = x_eval * cov * x_eval.transpose();
  f.sigma = std::sqrt(std::max(0.0, param_var) + s2 + floor * floor);
  f.ok = std::isfinite(f.value) && std::isfinite(f.sigma);
  return f;
}

}  // namespace

CurrentEstimate last_current(const std::vector<CurrentSample>& samples) { return last_current(samples, kSigmaFloorMS); }

CurrentEstimate last_current(const std::vector<CurrentSample>& samples, double floor) {
  CurrentEstimate e;
  e.samples = static_cast<int>(samples.size());
  if (samples.empty()) {
    e.method = "none";
    e.sigma_east_m_s = e.sigma_north_m_s = kNoHistorySigmaMS;
    return e;
  }
  e.east_m_s = samples.back().east_m_s;
  e.north_m_s = samples.back().north_m_s;
  // The scatter of consecutive estimates is what persistence costs.
  double se = 0.0, sn = 0.0;
  int n = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    se += std::pow(samples[i].east_m_s - samples[i - 1].east_m_s, 2);
    sn += std::pow(samples[i].north_m_s - samples[i - 1].north_m_s, 2);
    ++n;
  }
  const double fallback = 0.05;
  e.sigma_east_m_s = n > 0 ? std::hypot(std::sqrt(se / n), floor) : fallback;
  e.sigma_north_m_s = n > 0 ? std::hypot(std::sqrt(sn / n), floor) : fallback;
  e.method = "last";
  return e;
}

namespace {

// The fitted rules alone: `tidal` (mean + M2) or else the trend; nullopt
// when the history is too short for the rule asked.
std::optional<CurrentEstimate> predict_fitted(const std::vector<CurrentSample>& all, double from_utc_s, double to_utc_s,
                                              bool tidal, double floor) {
  // Only the last day counts: older water is other water.
  std::vector<CurrentSample> samples;
  for (const CurrentSample& s : all) {
    if (s.utc_s > from_utc_s - 86400.0 && s.utc_s <= from_utc_s) samples.push_back(s);
  }
  if (samples.empty()) return std::nullopt;
  const double span = samples.back().utc_s - samples.front().utc_s;
  const auto n = static_cast<Eigen::Index>(samples.size());
  const double t_ref = from_utc_s;
  const double mid = 0.5 * (from_utc_s + to_utc_s);
  CurrentEstimate e;
  e.samples = static_cast<int>(n);

  auto solve = [&](const std::vector<CurrentSample>& used, const Eigen::MatrixXd& x, const Eigen::VectorXd& w,
                   const Eigen::RowVectorXd& x_eval) {
    const auto m = static_cast<Eigen::Index>(used.size());
    Eigen::VectorXd ye(m), yn(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      ye(i) = used[static_cast<std::size_t>(i)].east_m_s;
      yn(i) = used[static_cast<std::size_t>(i)].north_m_s;
    }
    const Fit fe = least_squares(x, ye, w, x_eval, floor);
    const Fit fn = least_squares(x, yn, w, x_eval, floor);
    if (!fe.ok || !fn.ok) return false;
    e.east_m_s = fe.value;
    e.north_m_s = fn.value;
    e.sigma_east_m_s = fe.sigma;
    e.sigma_north_m_s = fn.sigma;
    return true;
  };

  if (tidal) {
    if (!(n >= 5 && span >= 9.0 * 3600.0)) return std::nullopt;
    // Mean + M2, averaged over the window (the integral of the harmonics).
    const double w2 = 2.0 * std::numbers::pi / kM2PeriodS;
    Eigen::MatrixXd x(n, 3);
    // Each estimate is the mean over its segment, and so is the prediction:
    // the harmonics averaged over [a, b] (a 3 h mean keeps 0.91 of an M2).
    auto averaged = [w2](double a, double b) {
      Eigen::RowVectorXd row(3);
      if (b - a < 1.0) {
        row << 1.0, std::cos(w2 * a), std::sin(w2 * a);
      } else {
        row << 1.0, (std::sin(w2 * b) - std::sin(w2 * a)) / (w2 * (b - a)),
            (std::cos(w2 * a) - std::cos(w2 * b)) / (w2 * (b - a));
      }
      return row;
    };
    for (Eigen::Index i = 0; i < n; ++i) {
      const CurrentSample& c = samples[static_cast<std::size_t>(i)];
      const double t = c.utc_s - t_ref;
      x.row(i) = averaged(t - 0.5 * c.span_s, t + 0.5 * c.span_s);
    }
    const double a = from_utc_s - t_ref, b = std::max(to_utc_s - t_ref, a + 1.0);
    const Eigen::RowVectorXd x_eval = averaged(a, b);
    if (!solve(samples, x, Eigen::VectorXd::Ones(n), x_eval)) return std::nullopt;
    e.method = "tidal fit";
    return e;
  }
  // A trend over the last 6 h, the recent weighted more (3 h e-folding).
  std::vector<CurrentSample> recent;
  for (const CurrentSample& s : samples) {
    if (s.utc_s > from_utc_s - 6.0 * 3600.0) recent.push_back(s);
  }
  if (recent.size() >= 3 && recent.back().utc_s - recent.front().utc_s >= 1.5 * 3600.0) {
    const auto m = static_cast<Eigen::Index>(recent.size());
    Eigen::MatrixXd x(m, 2);
    Eigen::VectorXd w(m);
    for (Eigen::Index i = 0; i < m; ++i) {
      const double t = recent[static_cast<std::size_t>(i)].utc_s - t_ref;
      x.row(i) << 1.0, t / 3600.0;
      w(i) = std::exp(t / (3.0 * 3600.0));
    }
    Eigen::RowVectorXd x_eval(2);
    x_eval << 1.0, (mid - t_ref) / 3600.0;
    if (solve(recent, x, w, x_eval)) {
      e.method = "trend";
      e.samples = static_cast<int>(m);
      return e;
    }
  }
  return std::nullopt;
}

}  // namespace

CurrentEstimate estimate_current(const std::vector<CurrentSample>& all, double from_utc_s, double to_utc_s,
                                 const TidalPrior& prior) {
  const bool use_prior = prior.mode != PriorMode::kOff;
  const double floor = prior.mode == PriorMode::kEvidence ? favoured_prior(all, from_utc_s, prior).estimate_sigma_m_s
                                                          : prior.estimate_sigma_m_s;
  // Each rule predicts every past estimate of the last day from the ones
  // before it (over a window as long as the coming one); the rule with the
  // smallest error wins, and its error is the estimate's uncertainty (the
  // hindcast says how well the rule does in this water, its formula does not).
  const double half = 0.5 * (to_utc_s - from_utc_s);
  // Persistence and its sigma: the scatter of consecutive estimates, pooled
  // with what the prior says carrying the last one over this window costs,
  // as two cases' worth (a scaled-inverse-chi-square prior, 2 degrees of
  // freedom): a few differences of a turning tide do not make persistence
  // certain. Without a prior, the scatter alone.
  auto persistence = [&](const std::vector<CurrentSample>& s, double from, double to) {
    CurrentEstimate e = last_current(s, floor);
    if (!use_prior || s.empty()) return e;
    const double prior_var = persistence_prior_variance(s.back(), from, to, prior, s);
    const double n = static_cast<double>(s.size() - 1), nu0 = 2.0;
    const double se2 = n > 0.0 ? e.sigma_east_m_s * e.sigma_east_m_s : 0.0;
    const double sn2 = n > 0.0 ? e.sigma_north_m_s * e.sigma_north_m_s : 0.0;
    e.sigma_east_m_s = std::sqrt((nu0 * prior_var + n * se2) / (nu0 + n));
    e.sigma_north_m_s = std::sqrt((nu0 * prior_var + n * sn2) / (nu0 + n));
    return e;
  };
  enum Rule { kLast, kTrend, kTidal, kPrior, kRules };
  // Squared errors of each rule, and of persistence on the same cases; and
  // each error in the sigma the rule gave it (z^2, east and north).
  double sum2[kRules] = {}, last_on[kRules] = {}, z2[kRules] = {};
  int count[kRules] = {};
  for (std::size_t j = 1; j < all.size(); ++j) {
    if (all[j].utc_s > from_utc_s || all[j].utc_s <= from_utc_s - 86400.0) continue;
    const std::vector<CurrentSample> before(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(j));
    const double from = all[j].utc_s - half, to = all[j].utc_s + half;
    auto error2 = [&](const CurrentEstimate& p) {
      return std::pow(p.east_m_s - all[j].east_m_s, 2) + std::pow(p.north_m_s - all[j].north_m_s, 2);
    };
    const double last2 = error2(last_current(before, floor));
    for (int rule = kLast; rule < kRules; ++rule) {
      std::optional<CurrentEstimate> p;
      if (rule == kLast) {
        p = persistence(before, from, to);
      } else if (rule == kPrior) {
        if (use_prior) p = predict_with_prior(before, from, to, prior);
      } else {
        p = predict_fitted(before, from, to, rule == kTidal, floor);
      }
      if (!p) continue;
      sum2[rule] += error2(*p);
      last_on[rule] += last2;
      z2[rule] += std::pow((p->east_m_s - all[j].east_m_s) / std::max(p->sigma_east_m_s, 1e-6), 2) +
                  std::pow((p->north_m_s - all[j].north_m_s) / std::max(p->sigma_north_m_s, 1e-6), 2);
      ++count[rule];
    }
  }
  if (all.empty()) return last_current(all, floor);
  // Fewer than two hindcasts (one or two estimates in the day): nothing can
  // choose a rule nor measure its error; the tidal prior gives both (a
  // turning tide makes persistence of one estimate wrong by more than any
  // difference of two estimates says).
  // Without a prior (the pilot's "off") persistence alone.
  if (count[kLast] < 2 && !use_prior) return last_current(all, floor);
  if (count[kLast] < 2) {
    CurrentEstimate e = predict_with_prior(all, from_utc_s, to_utc_s, prior);
    e.sigma_east_m_s = std::hypot(e.sigma_east_m_s, floor);
    e.sigma_north_m_s = std::hypot(e.sigma_north_m_s, floor);
    e.samples = static_cast<int>(all.size());
    return e;
  }
  int best = kLast;
  double best_gain = 1.0;
  for (int rule = kTrend; rule < kRules; ++rule) {
    // Two hindcasts at least: a tide shows itself in a few 3 h dives.
    if (count[rule] < 2) continue;
    const double gain = sum2[rule] / std::max(last_on[rule], 1e-12);  // < 1: better than persistence
    if (gain < best_gain) {
      best = rule;
      best_gain = gain;
    }
  }
  CurrentEstimate e = persistence(all, from_utc_s, to_utc_s);
  if (best == kPrior) {
    e = predict_with_prior(all, from_utc_s, to_utc_s, prior);
  } else if (best != kLast) {
    if (const std::optional<CurrentEstimate> p = predict_fitted(all, from_utc_s, to_utc_s, best == kTidal, floor))
      e = *p;
  }
  // The winner's sigma, scaled by how its hindcasts' errors compared with
  // the sigmas it gave them (sixth session): its formula said how sure it
  // is, the hindcasts say how sure it was right to be in this water. Pooled
  // with two cases' worth (east and north) of z^2 = 1, the formula taken at
  // its word. Before, the sigma was at least the hindcasts' RMS error: the
  // first hindcasts, from one or two estimates, made the later forecasts'
  // sigmas 2-3 times what their errors were (the current measured over the
  // SIL dives at an RMS 0.3-0.6 of the sigma) while the tidal fit's stayed
  // too narrow (1.2-1.7).
  const double pseudo = 4.0;
  const double scale = std::sqrt((pseudo + z2[best]) / (pseudo + 2.0 * count[best]));
  e.sigma_east_m_s = std::max(e.sigma_east_m_s * scale, floor);
  e.sigma_north_m_s = std::max(e.sigma_north_m_s * scale, floor);
  e.samples = static_cast<int>(all.size());
  return e;
}

CurrentEstimate estimate_current(const std::vector<CurrentSample>& samples, double from_utc_s, double to_utc_s) {
  return estimate_current(samples, from_utc_s, to_utc_s, TidalPrior{});
}

}  // namespace glider::forecast
