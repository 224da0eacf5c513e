// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/tidal_prior.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace glider::forecast {
namespace {

constexpr double kOmega = 2.0 * std::numbers::pi / kM2PeriodS;
// Evidence mode: each width scaled by 2^k, k = 1 .. -5 (x2 down to x1/32:
// from a tide twice the pilot's down to water with practically none).
constexpr int kScaleTop = 1, kScales = 7;
// The estimate's noise scaled by 1 .. 1/8: a glider (or a SIL) whose dead
// reckoning is better than the pilot's guess shows it in the estimates'
// scatter, and a noise that is too large shrinks a weak current to zero.
constexpr int kNoiseScales = 4;
// The position error (its hyperprior): scaled by 2 .. 1/8 or 0 (a
// precise glider: the segment's length does not matter, the SIL's 3 m fixes).
struct PositionScale {
  double scale, prior_weight;
};
// Half the weight on a precise glider (no position error: extrapolating two
// estimates of a tide stays as good as it was), half spread over 1/8-2 of
// the pilot's width. Chosen on synthetic two-estimate waters (the waters of
// forecast.CurrentNoise's ShortNoisySegmentsAreForecastBetterAndPreciseOnes-
// AtASmallCost, seed 11, 1000 draws) before the SIL and the real files: an even split over 2, 1, 1/2 and 0 cost a
// precise glider's 600 s estimate 0.009 -> 0.064 m/s RMS, this 0.009 -> 0.038, and a 100 m error's 0.33 -> 0.14 (0.12).
constexpr PositionScale kPositionScales[] = {{2.0, 0.1}, {1.0, 0.1}, {0.5, 0.1}, {0.25, 0.1}, {0.125, 0.1}, {0.0, 0.5}};
constexpr double kOctaveSigma = 1.0;

// A harmonic averaged over a span keeps sinc(omega span / 2) of its amplitude.
double kept(double span_s) {
  const double x = 0.5 * kOmega * span_s;
  return std::fabs(x) < 1e-9 ? 1.0 : std::sin(x) / x;
}

// Covariance of two segment means (middles t, spans s) under the prior: the
// mean's variance plus the tide's, cos(omega lag) of a random phase.
double random_phase_covariance(double t1, double s1, double t2, double s2, const TidalPrior& p) {
  return p.mean_sigma_m_s * p.mean_sigma_m_s +
         p.m2_sigma_m_s * p.m2_sigma_m_s * std::cos(kOmega * (t1 - t2)) * kept(s1) * kept(s2);
}

// The same for one component (0 east, 1 north); with the pilot's table the
// tide's part is the table's error in that component.
double covariance(double t1, double s1, double t2, double s2, const TidalPrior& p, int component) {
  if (!p.tide) return random_phase_covariance(t1, s1, t2, s2, p);
  return p.mean_sigma_m_s * p.mean_sigma_m_s +
         p.tide_error_scale * p.tide_error_scale * tide_error_covariance(*p.tide, component, t1, s1, t2, s2);
}

// The prior's mean of a segment's mean: zero, or the pilot's table.
double prior_mean(double t, double s, const TidalPrior& p, int component) {
  return p.tide ? tide_mean(*p.tide, component, t, s) : 0.0;
}

// An estimate's own error variance: the speed's noise and the position's
// error over its segment (a point estimate, span 0: the speed's alone).
double noise_variance(const CurrentSample& s, const TidalPrior& p) {
  const double position = s.span_s > 0.0 ? p.position_sigma_m / s.span_s : 0.0;
  return p.estimate_sigma_m_s * p.estimate_sigma_m_s + position * position;
}

std::vector<CurrentSample> last_day(const std::vector<CurrentSample>& all, double from_utc_s) {
  std::vector<CurrentSample> samples;
  for (const CurrentSample& s : all) {
    if (s.utc_s > from_utc_s - 86400.0 && s.utc_s <= from_utc_s) samples.push_back(s);
  }
  return samples;
}

// One hypothesis (fixed widths): the posterior mean over the window per
// component, its variance, and the log marginal likelihood of the estimates.
struct Posterior {
  double east = 0.0, north = 0.0, var_east = 0.0, var_north = 0.0;
  double log_evidence = 0.0;
  bool ok = true;
};

// With the pilot's table: one component (0 east, 1 north) conditioned on
// the estimates' residuals from the table (its own kernel: the table's error
// differs by component); its window's mean and variance, and log N(y; table,
// K) added to the evidence.
bool condition_component(const std::vector<CurrentSample>& samples, double t_w, double s_w, const TidalPrior& prior,
                         int c, Posterior& p) {
  const double prior_var = covariance(t_w, s_w, t_w, s_w, prior, c);
  double& mean = c == 0 ? p.east : p.north;
  double& var = c == 0 ? p.var_east : p.var_north;
  mean = prior_mean(t_w, s_w, prior, c);
  var = prior_var;
  if (samples.empty()) return true;
  const auto n = static_cast<Eigen::Index>(samples.size());
  Eigen::MatrixXd k(n, n);
  Eigen::VectorXd k_w(n), y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const CurrentSample& a = samples[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < n; ++j) {
      const CurrentSample& b = samples[static_cast<std::size_t>(j)];
      k(i, j) = covariance(a.utc_s, a.span_s, b.utc_s, b.span_s, prior, c);
    }
    k(i, i) += noise_variance(a, prior);
    k_w(i) = covariance(t_w, s_w, a.utc_s, a.span_s, prior, c);
    y(i) = (c == 0 ? a.east_m_s : a.north_m_s) - prior_mean(a.utc_s, a.span_s, prior, c);
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  if (llt.info() != Eigen::Success) return false;
  const Eigen::VectorXd weights = llt.solve(k_w);
  mean += weights.dot(y);
  var = std::max(prior_var - weights.dot(k_w), 0.0);
  const double log_det_half = llt.matrixLLT().diagonal().array().log().sum();
  p.log_evidence +=
      -0.5 * y.dot(llt.solve(y)) - log_det_half - 0.5 * static_cast<double>(n) * std::log(2.0 * std::numbers::pi);
  return true;
}

// Without a table east and north share the kernel and a zero prior mean:
// one factorisation for both (the rule before session 44, as it was).
Posterior condition_untabled(const std::vector<CurrentSample>& samples, double t_w, double s_w,
                             const TidalPrior& prior) {
  Posterior p;
  const double prior_var = random_phase_covariance(t_w, s_w, t_w, s_w, prior);
  p.var_east = p.var_north = prior_var;
  if (samples.empty()) return p;
  const auto n = static_cast<Eigen::Index>(samples.size());
  Eigen::MatrixXd k(n, n);
  Eigen::VectorXd k_w(n), y_e(n), y_n(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const CurrentSample& a = samples[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < n; ++j) {
      const CurrentSample& b = samples[static_cast<std::size_t>(j)];
      k(i, j) = random_phase_covariance(a.utc_s, a.span_s, b.utc_s, b.span_s, prior);
    }
    k(i, i) += noise_variance(a, prior);
    k_w(i) = random_phase_covariance(t_w, s_w, a.utc_s, a.span_s, prior);
    y_e(i) = a.east_m_s;
    y_n(i) = a.north_m_s;
  }
  // The noise on the diagonal keeps k positive definite.
  const Eigen::LLT<Eigen::MatrixXd> llt(k);
  if (llt.info() != Eigen::Success) {
    p.ok = false;
    return p;
  }
  const Eigen::VectorXd weights = llt.solve(k_w);
  p.east = weights.dot(y_e);
  p.north = weights.dot(y_n);
  p.var_east = p.var_north = std::max(prior_var - weights.dot(k_w), 0.0);
  // log N(y; 0, K) for east and north (independent, the same kernel).
  const Eigen::MatrixXd l = llt.matrixL();
  const double log_det = 2.0 * l.diagonal().array().log().sum();
  const double quad = y_e.dot(llt.solve(y_e)) + y_n.dot(llt.solve(y_n));
  p.log_evidence = -0.5 * quad - log_det - static_cast<double>(n) * std::log(2.0 * std::numbers::pi);
  return p;
}

Posterior condition(const std::vector<CurrentSample>& samples, double t_w, double s_w, const TidalPrior& prior) {
  if (!prior.tide) return condition_untabled(samples, t_w, s_w, prior);
  Posterior p;
  p.ok = condition_component(samples, t_w, s_w, prior, 0, p) && condition_component(samples, t_w, s_w, prior, 1, p);
  return p;
}

// The hypotheses and their posterior weights given `samples`.
struct Hypothesis {
  TidalPrior widths;
  Posterior posterior;
  double weight = 1.0;
};

std::vector<Hypothesis> weigh(const std::vector<CurrentSample>& samples, double t_w, double s_w,
                              const TidalPrior& prior) {
  std::vector<Hypothesis> out;
  if (prior.mode != PriorMode::kEvidence) {
    out.push_back({prior, condition(samples, t_w, s_w, prior), 1.0});
    return out;
  }
  for (int a = 0; a < kScales; ++a) {
    for (int b = 0; b < kScales; ++b) {
      for (int c = 0; c < kNoiseScales; ++c) {
        for (const PositionScale& position : kPositionScales) {
          Hypothesis h;
          h.widths = prior;
          h.widths.mean_sigma_m_s = prior.mean_sigma_m_s * std::ldexp(1.0, kScaleTop - a);
          h.widths.m2_sigma_m_s = prior.m2_sigma_m_s * std::ldexp(1.0, kScaleTop - b);
          h.widths.estimate_sigma_m_s = prior.estimate_sigma_m_s * std::ldexp(1.0, -c);
          h.widths.position_sigma_m = prior.position_sigma_m * position.scale;
          h.widths.tide_error_scale = prior.tide_error_scale * std::ldexp(1.0, kScaleTop - b);
          h.posterior = condition(samples, t_w, s_w, h.widths);
          // The hyperprior: the pilot's widths the likeliest, each octave away
          // less so (log-normal, kOctaveSigma octaves), the noises' uniform.
          const double da = kScaleTop - a, db = kScaleTop - b;
          h.posterior.log_evidence -= 0.5 * (da * da + db * db) / (kOctaveSigma * kOctaveSigma);
          h.posterior.log_evidence += std::log(position.prior_weight);
          if (h.posterior.ok) out.push_back(h);
        }
      }
    }
  }
  if (out.empty()) return out;
  double best = -INFINITY;
  for (const Hypothesis& h : out) best = std::max(best, h.posterior.log_evidence);
  double sum = 0.0;
  for (Hypothesis& h : out) sum += (h.weight = std::exp(h.posterior.log_evidence - best));
  for (Hypothesis& h : out) h.weight /= sum;
  return out;
}

}  // namespace

const char* to_string(PriorMode mode) {
  switch (mode) {
    case PriorMode::kEvidence:
      return "evidence";
    case PriorMode::kFixed:
      return "fixed";
    case PriorMode::kOff:
      return "off";
  }
  return "?";
}

PriorMode parse_prior_mode(const std::string& text) {
  if (text == "evidence") return PriorMode::kEvidence;
  if (text == "fixed") return PriorMode::kFixed;
  if (text == "off") return PriorMode::kOff;
  throw std::invalid_argument("'" + text + "' is not a prior mode (evidence, fixed or off)");
}

void check_prior(const TidalPrior& prior) {
  auto check = [](const char* name, double value, double low, double high, const char* unit) {
    if (!(value >= low && value <= high)) {  // NaN fails too
      throw std::invalid_argument(std::string(name) + " = " + std::to_string(value) + " is outside [" +
                                  std::to_string(low) + ", " + std::to_string(high) + "] " + unit);
    }
  };
  check("mean_sigma_m_s", prior.mean_sigma_m_s, 0.0, 2.0, "m/s");
  check("m2_sigma_m_s", prior.m2_sigma_m_s, 0.0, 2.0, "m/s");
  check("estimate_sigma_m_s", prior.estimate_sigma_m_s, 0.001, 1.0, "m/s");
  check("position_sigma_m", prior.position_sigma_m, 0.0, 5000.0, "m");
}

CurrentEstimate predict_with_prior(const std::vector<CurrentSample>& all, double from_utc_s, double to_utc_s,
                                   const TidalPrior& prior) {
  const std::vector<CurrentSample> samples = last_day(all, from_utc_s);
  const double t_w = 0.5 * (from_utc_s + to_utc_s), s_w = std::max(0.0, to_utc_s - from_utc_s);
  CurrentEstimate e;
  e.method = "tidal prior";
  e.samples = static_cast<int>(samples.size());
  // The mixture's mean and variance (per component) over the hypotheses.
  double m_e = 0.0, m_n = 0.0, s_e = 0.0, s_n = 0.0;
  for (const Hypothesis& h : weigh(samples, t_w, s_w, prior)) {
    m_e += h.weight * h.posterior.east;
    m_n += h.weight * h.posterior.north;
    s_e += h.weight * (h.posterior.var_east + h.posterior.east * h.posterior.east);
    s_n += h.weight * (h.posterior.var_north + h.posterior.north * h.posterior.north);
  }
  e.east_m_s = m_e;
  e.north_m_s = m_n;
  e.sigma_east_m_s = std::sqrt(std::max(s_e - m_e * m_e, 0.0));
  e.sigma_north_m_s = std::sqrt(std::max(s_n - m_n * m_n, 0.0));
  return e;
}

double persistence_prior_variance(const CurrentSample& last, double from_utc_s, double to_utc_s,
                                  const TidalPrior& prior, const std::vector<CurrentSample>& samples) {
  const double t_w = 0.5 * (from_utc_s + to_utc_s), s_w = std::max(0.0, to_utc_s - from_utc_s);
  double var = 0.0;
  for (const Hypothesis& h : weigh(last_day(samples, from_utc_s), t_w, s_w, prior)) {
    const TidalPrior& p = h.widths;
    // E(W - S)^2 = Var W + Var S - 2 Cov(W, S) + (the prior's mean change)^2, S carrying the estimate's
    // own error; the mean of the two components (one without a table: both the same).
    if (!p.tide) {
      var += h.weight * (random_phase_covariance(t_w, s_w, t_w, s_w, p) +
                         random_phase_covariance(last.utc_s, last.span_s, last.utc_s, last.span_s, p) +
                         noise_variance(last, p) - 2.0 * random_phase_covariance(t_w, s_w, last.utc_s, last.span_s, p));
      continue;
    }
    for (int c = 0; c < 2; ++c) {
      const double change = prior_mean(t_w, s_w, p, c) - prior_mean(last.utc_s, last.span_s, p, c);
      var +=
          0.5 * h.weight *
          (covariance(t_w, s_w, t_w, s_w, p, c) + covariance(last.utc_s, last.span_s, last.utc_s, last.span_s, p, c) +
           noise_variance(last, p) - 2.0 * covariance(t_w, s_w, last.utc_s, last.span_s, p, c) + change * change);
    }
  }
  return var;
}

TidalPrior favoured_prior(const std::vector<CurrentSample>& samples, double from_utc_s, const TidalPrior& prior) {
  TidalPrior out = prior;
  if (prior.mode != PriorMode::kEvidence) return out;
  out.mean_sigma_m_s = out.m2_sigma_m_s = out.estimate_sigma_m_s = out.position_sigma_m = out.tide_error_scale = 0.0;
  for (const Hypothesis& h : weigh(last_day(samples, from_utc_s), from_utc_s, 0.0, prior)) {
    out.mean_sigma_m_s += h.weight * h.widths.mean_sigma_m_s;
    out.m2_sigma_m_s += h.weight * h.widths.m2_sigma_m_s;
    out.estimate_sigma_m_s += h.weight * h.widths.estimate_sigma_m_s;
    out.position_sigma_m += h.weight * h.widths.position_sigma_m;
    out.tide_error_scale += h.weight * h.widths.tide_error_scale;
  }
  return out;
}

}  // namespace glider::forecast
