// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/least_squares_functor.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <unsupported/Eigen/NonLinearOptimization>
#include <utility>

#include "glider/diagnose/depth_lag.hpp"
#include "glider/diagnose/dynamic_flight_model.hpp"
#include "glider/diagnose/forward_difference.hpp"
#include "glider/diagnose/speed_reference.hpp"
#include "glider/diagnose/stall_branch.hpp"
#include "glider/diagnose/thin.hpp"
#include "glider/fitting_core/block_score.hpp"
#include "glider/fitting_core/delay_search.hpp"
#include "glider/fitting_core/effective_samples.hpp"
#include "glider/fitting_core/identifiability.hpp"
#include "glider/fitting_core/intervals.hpp"
#include "glider/fitting_core/profile_check.hpp"
#include "glider/fitting_core/selection.hpp"
#include "glider/fitting_core/stepwise.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

using namespace fitting_core;  // NOLINT(google-build-using-namespace): the one fitting core

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A sample the model cannot fly (no steady glide) counts as this error: an
// effect must not "improve" the fit by making samples unflyable.
constexpr double kUnflyablePenalty_m_s = 0.3;

// Effects fitted as |value|: a lag has no sign.
bool is_lag(Effect e) { return e == Effect::kPumpLag || e == Effect::kDepthLag; }

struct Candidate {
  std::vector<Effect> fitted;  // effects with fitted parameters
  bool ctd_density = false;    // water_density from the CTD (no parameter)
};

// The samples a model is scored on: the steady model's steady-glide samples
// (observations), or every settled sample of the log for the dynamic model
// (track, turns included).
struct SampleSet {
  const DepthRateModel& model;
  std::span<const double> depth_m, measured_m_s, time_s;
  std::span<const int> yo;
  std::vector<flightlog::Phase> phase;
  std::vector<std::size_t> usable;  // sorted indices of the samples scored
  // Per lag effect and density input (the CTD's or the constant's), the
  // best point of its grid over the allowed range (lag_grid_start):
  // computed at the first fit that needs it, once per diagnosis (the
  // training samples are the same in every fit).
  mutable std::map<std::pair<Effect, bool>, double> lag_start{};
};

// How the optimiser's parameter vector maps onto effects: one scaled number
// per effect (value = nominal + scale * p), except the vertical water
// velocity, which has one per depth bin.
struct Layout {
  std::vector<std::size_t> offset;  // into p, per fitted effect
  std::size_t size = 0;
  VerticalVelocityProfile bins;    // the bin geometry (values filled per evaluation)
  std::vector<double> bin_weight;  // fraction of the fitted samples in each bin
};

Layout make_layout(const Candidate& c, const SampleSet& obs, std::span<const std::size_t> train) {
  Layout layout;
  double top = 1e9, bottom = -1e9;
  for (std::size_t i : train) {
    top = std::min(top, obs.depth_m[i]);
    bottom = std::max(bottom, obs.depth_m[i]);
  }
  layout.bins.first_m = std::floor(top / layout.bins.bin_m) * layout.bins.bin_m;
  const std::size_t bins =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil((bottom - layout.bins.first_m) / layout.bins.bin_m)));
  layout.bins.w_m_s.assign(bins, 0.0);
  layout.bin_weight.assign(bins, 0.0);
  for (std::size_t i : train) {
    const double position = (obs.depth_m[i] - layout.bins.first_m) / layout.bins.bin_m;
    const std::size_t b = std::min(bins - 1, static_cast<std::size_t>(std::max(0.0, std::floor(position))));
    layout.bin_weight[b] += 1.0 / static_cast<double>(train.size());
  }
  for (Effect e : c.fitted) {
    layout.offset.push_back(layout.size);
    layout.size += e == Effect::kVerticalWaterVelocity ? bins : 1;
  }
  return layout;
}

struct Parameters {
  EffectValues values = nominal_values();
  std::optional<VerticalVelocityProfile> profile;
};

Parameters unpack(const Candidate& c, const Layout& layout, const Eigen::VectorXd& p) {
  Parameters out;
  for (std::size_t j = 0; j < c.fitted.size(); ++j) {
    const Effect e = c.fitted[j];
    const EffectInfo& ei = info(e);
    const auto o = static_cast<Eigen::Index>(layout.offset[j]);
    if (e == Effect::kVerticalWaterVelocity) {
      VerticalVelocityProfile profile = layout.bins;
      double mean = 0.0;
      for (std::size_t b = 0; b < profile.w_m_s.size(); ++b) {
        profile.w_m_s[b] = ei.scale * p[o + static_cast<Eigen::Index>(b)];
        mean += layout.bin_weight[b] * profile.w_m_s[b];
      }
      out.values[static_cast<std::size_t>(e)] = mean;  // the reported value: the mean over the log
      out.profile = profile;
    } else {
      out.values[static_cast<std::size_t>(e)] = ei.nominal + ei.scale * p[o];
    }
  }
  return out;
}

// Residuals (model - measured) of a set of samples.
void residuals(const SampleSet& set, const Parameters& x, bool ctd, std::span<const std::size_t> samples,
               std::vector<double>& out) {
  std::vector<double> predicted;
  set.model.predict(x.values, ctd, samples, predicted, x.profile ? &*x.profile : nullptr);
  out.resize(samples.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double p = predicted[k];
    out[k] = std::isfinite(p) ? p - set.measured_m_s[samples[k]] : kUnflyablePenalty_m_s;
  }
}

// Residuals of two disjoint sets of samples (the fitted and the held-out
// yos) from one flight through the log: a sample's prediction does not
// depend on which others are asked for.
void residuals_of_both(const SampleSet& set, const Parameters& x, bool ctd, std::span<const std::size_t> a,
                       std::span<const std::size_t> b, std::vector<double>& out_a, std::vector<double>& out_b) {
  std::vector<std::size_t> both;
  both.reserve(a.size() + b.size());
  std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  std::vector<double> r;
  residuals(set, x, ctd, both, r);
  out_a.clear();
  out_b.clear();
  for (std::size_t k = 0; k < both.size(); ++k) {
    (out_a.size() < a.size() && both[k] == a[out_a.size()] ? out_a : out_b).push_back(r[k]);
  }
}

double rms_of(const std::vector<double>& r) {
  if (r.empty()) return kNaN;
  double s = 0.0;
  for (double v : r) s += v * v;
  return std::sqrt(s / static_cast<double>(r.size()));
}

// Eigen's Levenberg-Marquardt functor over the scaled parameters.
struct FitFunctor : LeastSquaresFunctor {
  const SampleSet& set;
  const Candidate& candidate;
  const Layout& layout;
  std::span<const std::size_t> samples;
  mutable std::vector<double> buffer;

  int inputs() const { return static_cast<int>(layout.size); }
  int values() const { return static_cast<int>(samples.size()); }
  int operator()(const Eigen::VectorXd& p, Eigen::VectorXd& f) const {
    residuals(set, unpack(candidate, layout, p), candidate.ctd_density, samples, buffer);
    for (std::size_t k = 0; k < buffer.size(); ++k) f[static_cast<Eigen::Index>(k)] = buffer[k];
    return 0;
  }
};

// The uncertainty of the fitted (scaled) parameters by the interval rule
// (fitting_core/intervals.hpp): glider residuals are not independent noise,
// a glide's samples share one model error.
ParameterUncertainty parameter_uncertainty(const SampleSet& set, std::span<const std::size_t> train,
                                           const Eigen::MatrixXd& jac, const std::vector<double>& r,
                                           DiagnoseOptions::Intervals intervals) {
  std::vector<long> cluster;  // a glide (a dive, a climb or a turn of one yo) or a yo
  cluster.reserve(train.size());
  for (std::size_t sample : train) {
    cluster.push_back(cluster_of(intervals, set.yo[sample], static_cast<int>(set.phase[sample])));
  }
  return {jac, r, cluster, intervals};
}

struct FitResult {
  Parameters parameters;
  Eigen::VectorXd p;                    // the optimiser's (scaled) solution
  std::vector<double> train_residuals;  // at p
  // Per fitted effect, reported units (the mean's, for a profile); empty
  // until add_intervals(): a Jacobian costs a flight per parameter, and
  // most candidate fits are only compared, never reported.
  std::vector<double> sigma;
  double train_rss = 0.0;
  double heldout_rms = 0.0;    // sample by sample: the error reported
  double heldout_score = 0.0;  // over blocks of a glide: the error selected by (block_score.hpp)
  double bic = 0.0;
  Score score() const { return {heldout_score, bic}; }
};

// The grid a lag is searched on, 0 to its plausible maximum: the depth lag
// every 1 s (its scale; 11 points that reuse one flight), the pump lag
// doubling from its scale (0, 2.5, 5, 10, ... 80, 120 s: 8 flights through
// the log - every 5 s, 25 flights, cost a 24 h log 0.7 s of CPU, a third).
DelayGrid lag_grid(Effect e) {
  return e == Effect::kDepthLag ? delay_grid(0.0, info(e).plausible_max, info(e).scale)
                                : doubling_delay_grid(info(e).scale, info(e).plausible_max);
}

// The training RSS of `x`.
double train_rss_at(const SampleSet& set, const Parameters& x, bool ctd, std::span<const std::size_t> train) {
  std::vector<double> r;
  residuals(set, x, ctd, train, r);
  double rss = 0.0;
  for (double v : r) rss += v * v;
  return rss;
}

// Global step of the lag's global-then-local search: the lag alone (every
// other effect nominal, the candidate's density input) on its grid; the
// local fit then starts at the best point. Once per lag, density input and
// diagnosis (SampleSet::lag_start): 8 flights for the pump lag instead of a
// start in the nearest minimum (a hidden 37.9 s lag started at 5 s lost to
// a lift change 0.80 + depth lag 5.9 s; tests/diagnose/test_long_delays.cpp).
// The density input is part of the key: a grid run with the constant
// density where the fit uses the CTD's put a 14.7 s lag's start at 5 s, on
// a shoulder of the CTD fit's residual the local fit stopped on (5.6 s,
// tests/diagnose_pump_lag).
double lag_grid_start(const SampleSet& set, Effect e, bool ctd, std::span<const std::size_t> train) {
  if (const auto it = set.lag_start.find({e, ctd}); it != set.lag_start.end()) return it->second;
  const DelayGrid grid = lag_grid(e);
  const std::vector<double> rss = rss_on_grid(grid, [&](double lag) {
    Parameters x{nominal_values(), std::nullopt};
    x.values[static_cast<std::size_t>(e)] = lag;
    return train_rss_at(set, x, ctd, train);
  });
  const double start = best_on_grid(grid, rss);
  set.lag_start.emplace(std::pair{e, ctd}, start);
  return start;
}

// The held-out residuals `h` (of `heldout`) averaged over blocks of a glide
// (fitting_core/block_score.hpp).
double heldout_block_rms(const SampleSet& set, std::span<const std::size_t> heldout, const std::vector<double>& h,
                         double block_s) {
  std::vector<double> time(heldout.size());
  std::vector<long> glide(heldout.size());
  for (std::size_t k = 0; k < heldout.size(); ++k) {
    time[k] = set.time_s[heldout[k]];
    glide[k] = cluster_of(IntervalRule::kGlides, set.yo[heldout[k]], static_cast<int>(set.phase[heldout[k]]));
  }
  return block_rms(time, glide, h, block_s);
}

// `from`, where given: a fit of some of the candidate's effects (the rest start
// as below), its values the start.
FitResult fit(const SampleSet& set, const Candidate& candidate, std::span<const std::size_t> train,
              std::span<const std::size_t> heldout, double score_block_s, const FitResult* from = nullptr) {
  FitResult result;
  const Layout layout = make_layout(candidate, set, train);
  const std::size_t k = layout.size;
  Eigen::VectorXd& p = result.p;
  p = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
  // The lags are fitted as |value| (no sign): each starts at the best point
  // of its grid (lag_grid_start), or a fifth of a scale (1 s, 0.2 s) from 0
  // where that is 0 (at 0 the gradient vanishes; from a full scale the fit
  // took longer to come back: 24 h log 2.35-2.50 -> 2.22-2.30 s of CPU).
  for (std::size_t j = 0; j < candidate.fitted.size(); ++j) {
    const Effect e = candidate.fitted[j];
    if (!is_lag(e)) continue;
    const double start = lag_grid_start(set, e, candidate.ctd_density, train);
    p[static_cast<Eigen::Index>(layout.offset[j])] = start > 0.0 ? (start - info(e).nominal) / info(e).scale : 0.2;
  }
  if (from != nullptr) {
    for (std::size_t j = 0; j < candidate.fitted.size(); ++j) {
      const Effect e = candidate.fitted[j];
      const auto o = static_cast<Eigen::Index>(layout.offset[j]);
      const std::size_t f = static_cast<std::size_t>(e);
      if (e == Effect::kVerticalWaterVelocity) {
        const auto& profile = from->parameters.profile;
        if (!profile || profile->w_m_s.size() != layout.bins.w_m_s.size()) continue;
        for (std::size_t b = 0; b < profile->w_m_s.size(); ++b) {
          p[o + static_cast<Eigen::Index>(b)] = profile->w_m_s[b] / info(e).scale;
        }
      } else if (from->parameters.values[f] != info(e).nominal) {  // fitted there
        p[o] = (from->parameters.values[f] - info(e).nominal) / info(e).scale;
      }
    }
  }
  if (k > 0) {
    const ForwardDifference<FitFunctor> functor(FitFunctor{{}, set, candidate, layout, train, {}});
    Eigen::LevenbergMarquardt<const ForwardDifference<FitFunctor>> lm(functor);
    lm.parameters.maxfev = 400;
    lm.minimize(p);
  }
  result.parameters = unpack(candidate, layout, p);
  std::vector<double> h;
  residuals_of_both(set, result.parameters, candidate.ctd_density, train, heldout, result.train_residuals, h);
  const double n = static_cast<double>(result.train_residuals.size());
  for (double v : result.train_residuals) result.train_rss += v * v;
  result.bic = bic(result.train_rss, n, static_cast<double>(k));
  result.heldout_rms = rms_of(h);
  result.heldout_score = heldout_block_rms(set, heldout, h, score_block_s);
  return result;
}

// A lag's uncertainty where the Jacobian gives none (a flat or exact
// residual: a zero-width interval): the 95 % profile over its grid, the other
// parameters held at the fit (a conditional profile), as a sigma whose
// 1.96 sigma reaches the farther bound - never less than half a grid step,
// the grid's resolution.
double lag_profile_sigma(const SampleSet& set, const Candidate& candidate, std::span<const std::size_t> train,
                         const FitResult& f, std::size_t j, std::size_t parameters) {
  const Effect e = candidate.fitted[j];
  const DelayGrid grid = lag_grid(e);
  const double value = std::abs(f.parameters.values[static_cast<std::size_t>(e)]);
  const std::vector<double> rss = rss_on_grid(grid, [&](double lag) {
    Parameters x = f.parameters;
    x.values[static_cast<std::size_t>(e)] = lag;
    std::vector<double> r;
    residuals(set, x, candidate.ctd_density, train, r);
    double s = 0.0;
    for (double v : r) s += v * v;
    return s;
  });
  const auto k = static_cast<int>(parameters);
  const double n_eff = std::max(effective_sample_count(f.train_residuals, 0.0), static_cast<double>(k) + 2.0);
  const Interval profile = at_least_resolution(profile_interval(grid, rss, value, f.train_rss, n_eff, k), value,
                                               resolution_at(grid, value), 0.0);
  return std::max(value - profile.low, profile.high - value) / kZ95;
}

// A sigma the residual itself supports (fitting_core/profile_check.hpp): the
// Jacobian's where the training RSS rises at its 95 % ends as it should, else
// the conditional profile's (the other parameters held at the fit) - a
// forward difference across a step of the flight gave thermal expansion a
// zero-width interval. Two flights where the Jacobian holds.
double profile_checked_sigma(const SampleSet& set, const Candidate& candidate, std::span<const std::size_t> train,
                             const FitResult& f, std::size_t j, std::size_t parameters, double sigma) {
  const auto e = static_cast<std::size_t>(candidate.fitted[j]);
  const double value = f.parameters.values[e];
  const double n_eff = std::max(effective_sample_count(f.train_residuals, 0.0), static_cast<double>(parameters) + 2.0);
  std::vector<double> r;
  const auto rss_at = [&](double x) {
    Parameters moved = f.parameters;
    moved.values[e] = x;
    residuals(set, moved, candidate.ctd_density, train, r);
    double s = 0.0;
    for (double v : r) s += v * v;
    return s;
  };
  const double half = profile_checked_half_width(value, kZ95 * sigma, f.train_rss, n_eff, static_cast<int>(parameters),
                                                 1e-6 * info(candidate.fitted[j]).scale, rss_at);
  return half / kZ95;
}

// Parameter uncertainty of `f` (a fit of `candidate`) from the Jacobian at
// its solution, with the residuals' serial correlation respected
// (DiagnoseOptions::intervals). Once per fit: a no-op when it has them.
void add_intervals(const SampleSet& set, const Candidate& candidate, std::span<const std::size_t> train,
                   DiagnoseOptions::Intervals intervals, FitResult& f) {
  const Layout layout = make_layout(candidate, set, train);
  const std::size_t k = layout.size;
  if (k == 0 || !f.sigma.empty()) return;
  const std::vector<double>& r = f.train_residuals;
  const ForwardDifference<FitFunctor> functor(FitFunctor{{}, set, candidate, layout, train, {}});
  Eigen::MatrixXd jac(static_cast<Eigen::Index>(train.size()), static_cast<Eigen::Index>(k));
  functor.remember(f.p, Eigen::Map<const Eigen::VectorXd>(r.data(), static_cast<Eigen::Index>(r.size())));
  functor.df(f.p, jac);
  const ParameterUncertainty uncertainty = parameter_uncertainty(set, train, jac, r, intervals);
  for (std::size_t j = 0; j < candidate.fitted.size(); ++j) {
    const Effect e = candidate.fitted[j];
    const auto o = static_cast<Eigen::Index>(layout.offset[j]);
    Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(k));
    if (e == Effect::kVerticalWaterVelocity) {  // the weighted mean of the bins
      for (std::size_t b = 0; b < layout.bin_weight.size(); ++b)
        w[o + static_cast<Eigen::Index>(b)] = layout.bin_weight[b];
    } else {
      w[o] = 1.0;
    }
    double sigma = uncertainty.sigma(w) * info(e).scale;
    if (is_lag(e) && jacobian_failed(kZ95 * sigma, info(e).scale)) {
      sigma = lag_profile_sigma(set, candidate, train, f, j, k);
    } else if (!is_lag(e) && e != Effect::kVerticalWaterVelocity) {
      sigma = profile_checked_sigma(set, candidate, train, f, j, k, sigma);
    }
    f.sigma.push_back(sigma);
  }
}

// fit(), announced first to options.progress (one call per model fit: the
// unit of diagnose's cost, seconds each on a long log).
FitResult fit_reported(const SampleSet& set, const Candidate& candidate, std::span<const std::size_t> train,
                       std::span<const std::size_t> heldout, const DiagnoseOptions& options,
                       const FitResult* from = nullptr) {
  if (options.progress) {
    std::string what = candidate.ctd_density ? "ctd_density" : "";
    for (Effect e : candidate.fitted) {
      if (!what.empty()) what.push_back('+');
      what.append(info(e).id);
    }
    options.progress(what.empty() ? "nominal" : what);
  }
  return fit(set, candidate, train, heldout, options.score_block_s, from);
}

Rms rms_where(const std::vector<double>& r, const std::vector<std::size_t>& idx) {
  Rms out;
  double s = 0.0;
  for (std::size_t i : idx) {
    if (!std::isfinite(r[i])) continue;
    s += r[i] * r[i];
    ++out.samples;
  }
  out.depth_rate_m_s = out.samples ? std::sqrt(s / static_cast<double>(out.samples)) : kNaN;
  return out;
}

// Pitch trim: the battery the servo needed to hold the logged pitch against
// the one the nominal model needs. A CG error shows as the same offset on
// dives and climbs (the vocabulary's pitch_trim_offset, + = nose-heavy, as if
// the battery were further forward: the servo then sits further aft).
void diagnose_pitch_trim(const FlightModel& model, const Observations& obs, std::span<const std::size_t> train,
                         std::span<const std::size_t> heldout, const DiagnoseOptions& options, Diagnosis& d) {
  if (!obs.has_battpos) return;
  std::vector<long> glide;  // of each training difference (the interval's clusters)
  auto differences = [&](std::span<const std::size_t> samples, std::vector<long>* cluster) {
    std::vector<double> out;
    for (std::size_t i : samples) {
      const double required = model.required_battpos_in(i, d.extended, d.extended_uses_ctd_density);
      if (!std::isfinite(required) || !std::isfinite(obs.battpos_in[i])) continue;
      out.push_back(obs.battpos_in[i] - required);
      if (cluster) cluster->push_back(cluster_of(options.intervals, obs.yo[i], obs.diving[i] ? 0 : 1));
    }
    return out;
  };
  const std::vector<double> fit_part = differences(train, &glide);
  const std::vector<double> held = differences(heldout, nullptr);
  if (fit_part.size() < 10 || held.empty()) return;
  // The battery's offset: the mean difference, its interval by the one rule
  // of every fit (a bang-bang battery holds one position a glide: glides
  // are the independent samples).
  const Estimate offset = mean_with_rule(fit_part, glide, options.intervals);
  const double mean = offset.value;
  std::vector<double> after(held);
  for (double& x : after) x -= mean;
  const double before_rms = rms_of(held);
  const double after_rms = rms_of(after);
  std::vector<double> all_differences(fit_part);
  all_differences.insert(all_differences.end(), held.begin(), held.end());
  d.baseline.rms_battpos_in = rms_of(all_differences);
  const double value = -mean;  // nose-heavy = the servo holds the battery aft of the model's
  // As for the depth rate: relative and absolute (0.01 in: the slide's resolution) improvements.
  const double half = 0.5 * (offset.high - offset.low);
  if (std::abs(value) > half && improves_heldout(after_rms, before_rms, {options.margins.relative, 0.01})) {
    Finding f;
    f.effect = Effect::kPitchTrimOffset;
    f.value = value;
    f.ci95_low = value - half;
    f.ci95_high = value + half;
    f.heldout_rms_m_s = d.findings.empty() ? d.baseline.heldout_rms_m_s : d.findings.back().heldout_rms_m_s;
    f.gain = d.findings.empty() ? 0.0 : d.findings.back().gain;
    f.heldout_rms_battpos_in = after_rms;
    d.findings.push_back(f);
    d.extended[static_cast<std::size_t>(Effect::kPitchTrimOffset)] = value;
  }
}

// Alternate yos: even ones fit, odd ones are held out (a log of one yo is
// split in halves by time instead).
void split_by_yo(std::span<const std::size_t> samples, std::span<const int> yo, std::vector<std::size_t>& train,
                 std::vector<std::size_t>& heldout) {
  for (std::size_t i : samples) (yo[i] % 2 == 0 ? train : heldout).push_back(i);
  if (train.empty() || heldout.empty()) {
    train.assign(samples.begin(), samples.begin() + static_cast<long>(samples.size() / 2));
    heldout.assign(samples.begin() + static_cast<long>(samples.size() / 2), samples.end());
  }
}

SampleSet steady_set(const DepthRateModel& model, const Observations& obs) {
  SampleSet set{model, obs.depth_m, obs.depth_rate_m_s, obs.time_s, obs.yo, {}, {}, {}};
  for (std::size_t i = 0; i < obs.size(); ++i) {
    set.phase.push_back(obs.diving[i] ? flightlog::Phase::kDive : flightlog::Phase::kClimb);
    set.usable.push_back(i);
  }
  return set;
}

SampleSet dynamic_set(const DepthRateModel& model, const Track& track) {
  return {model, track.depth_m, track.depth_rate_m_s, track.time_s, track.yo, track.phase, track.scored, {}};
}

std::vector<std::size_t> where_phase(const SampleSet& set, flightlog::Phase phase) {
  std::vector<std::size_t> out;
  for (std::size_t i : set.usable) {
    if (set.phase[i] == phase) out.push_back(i);
  }
  return out;
}

double rms_difference(const std::vector<double>& a, std::span<const double> b, std::span<const std::size_t> idx,
                      std::size_t& count) {
  double s = 0.0;
  count = 0;
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const double m = b[idx[k]];
    if (!std::isfinite(m) || !std::isfinite(a[k])) continue;
    s += (a[k] - m) * (a[k] - m);
    ++count;
  }
  return count ? std::sqrt(s / static_cast<double>(count)) : kNaN;
}

// The two models' speed error yo by yo (`nominal`, `extended` at `measured`).
std::vector<SpeedOfYo> speed_by_yo(const std::vector<double>& nominal, const std::vector<double>& extended,
                                   std::span<const double> truth, std::span<const std::size_t> measured,
                                   std::span<const int> yo, std::span<const std::size_t> measured_heldout) {
  std::vector<SpeedOfYo> out;
  for (std::size_t k = 0; k < measured.size(); ++k) {
    const std::size_t i = measured[k];
    if (!std::isfinite(nominal[k]) || !std::isfinite(extended[k])) continue;
    if (out.empty() || out.back().yo != yo[i]) {
      out.emplace_back();
      out.back().yo = yo[i];
      out.back().heldout = std::binary_search(measured_heldout.begin(), measured_heldout.end(), i);
    }
    SpeedOfYo& s = out.back();
    ++s.samples;
    s.measured_mean_m_s += truth[i];
    s.nominal_mean_m_s += nominal[k];
    s.nominal_rms_m_s += (nominal[k] - truth[i]) * (nominal[k] - truth[i]);
    s.extended_mean_m_s += extended[k];
    s.extended_rms_m_s += (extended[k] - truth[i]) * (extended[k] - truth[i]);
  }
  for (SpeedOfYo& s : out) {
    const auto n = static_cast<double>(s.samples);
    s.measured_mean_m_s /= n;
    s.nominal_mean_m_s /= n;
    s.nominal_rms_m_s = std::sqrt(s.nominal_rms_m_s / n);
    s.extended_mean_m_s /= n;
    s.extended_rms_m_s = std::sqrt(s.extended_rms_m_s / n);
  }
  return out;
}

// RMS over the yos (all, or the held-out ones) whose reference speed is
// consistent, from each yo's RMS and sample count.
double consistent_rms(const std::vector<SpeedOfYo>& by_yo, bool heldout_only, double SpeedOfYo::*rms) {
  double sum = 0.0;
  std::size_t n = 0;
  for (const SpeedOfYo& y : by_yo) {
    if (!y.reference_consistent || (heldout_only && !y.heldout)) continue;
    sum += y.*rms * y.*rms * static_cast<double>(y.samples);
    n += y.samples;
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : kNaN;
}

// Whether each yo's reference speed belongs to its measured depth rate and
// pitch (speed_reference.hpp), with the extended model's glide path; then
// the scores over the consistent yos.
void check_reference(const SampleSet& set, std::span<const std::size_t> measured, const Parameters& extended, bool ctd,
                     std::span<const double> truth, const std::vector<double>& u_extended, SpeedScore& score) {
  std::vector<double> rate;
  set.model.predict(extended.values, ctd, measured, rate, extended.profile ? &*extended.profile : nullptr);
  const double constant_w = extended.values[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)];
  std::vector<double> implied(measured.size());
  std::vector<int> yo(measured.size());
  for (std::size_t k = 0; k < measured.size(); ++k) {
    const std::size_t i = measured[k];
    const double water = extended.profile ? extended.profile->at(set.depth_m[i]) : constant_w;
    implied[k] = implied_water_velocity(set.measured_m_s[i], rate[k] - water, truth[i], u_extended[k]);
    yo[k] = set.yo[i];
  }
  score.implied_water_w_median_m_s =
      check_reference_by_yo(score.by_yo, implied, yo, info(Effect::kVerticalWaterVelocity).plausible_max);
  score.consistent_nominal_rms_m_s = consistent_rms(score.by_yo, false, &SpeedOfYo::nominal_rms_m_s);
  score.consistent_extended_rms_m_s = consistent_rms(score.by_yo, false, &SpeedOfYo::extended_rms_m_s);
  score.heldout_consistent_nominal_rms_m_s = consistent_rms(score.by_yo, true, &SpeedOfYo::nominal_rms_m_s);
  score.heldout_consistent_extended_rms_m_s = consistent_rms(score.by_yo, true, &SpeedOfYo::extended_rms_m_s);
}

std::optional<SpeedScore> score_speed(const SampleSet& set, std::span<const std::size_t> all,
                                      std::span<const std::size_t> heldout, const Parameters& extended, bool ctd) {
  const DepthRateModel& model = set.model;
  const std::span<const int> yo = set.yo;
  const std::span<const double> truth = model.measured_speed_m_s();
  std::vector<std::size_t> measured, measured_heldout;
  for (std::size_t i : all) {
    if (std::isfinite(truth[i])) measured.push_back(i);
  }
  for (std::size_t i : heldout) {
    if (std::isfinite(truth[i])) measured_heldout.push_back(i);
  }
  if (measured.empty()) return std::nullopt;
  SpeedScore score;
  std::vector<double> u;
  for (std::size_t i : measured) score.measured_mean_m_s += truth[i] / static_cast<double>(measured.size());
  std::vector<double> u_nominal;
  model.predict_speed(nominal_values(), false, measured, u_nominal);
  score.nominal_rms_m_s = rms_difference(u_nominal, truth, measured, score.samples);
  model.predict_speed(extended.values, ctd, measured, u);
  score.extended_rms_m_s = rms_difference(u, truth, measured, score.samples);
  score.by_yo = speed_by_yo(u_nominal, u, truth, measured, yo, measured_heldout);
  check_reference(set, measured, extended, ctd, truth, u, score);
  model.predict_speed(nominal_values(), false, measured_heldout, u);
  score.heldout_nominal_rms_m_s = rms_difference(u, truth, measured_heldout, score.heldout_samples);
  model.predict_speed(extended.values, ctd, measured_heldout, u);
  score.heldout_extended_rms_m_s = rms_difference(u, truth, measured_heldout, score.heldout_samples);
  return score;
}

// A finding before its value is known (that comes from the final joint fit).
Finding new_finding(Effect effect, double heldout_rms_m_s, const Diagnosis& d) {
  Finding finding;
  finding.effect = effect;
  finding.fitted = effect != Effect::kWaterDensity;
  finding.heldout_rms_m_s = heldout_rms_m_s;
  finding.gain = 1.0 - heldout_rms_m_s / d.baseline.heldout_rms_m_s;
  return finding;
}

// A glider is ballasted for the water it will fly in: a nominal vehicle
// trimmed for 1025 kg/m^3 would sink like a stone in the Baltic's 1005 (1.2 kg
// heavy). When the log's measured density is that far from the vehicle's trim
// density, the vehicle is taken as trimmed for the log's median density, and
// the diagnosis says so.
std::optional<double> retrim_density(const model::VehicleParams& nominal, const Observations& obs,
                                     double tolerance_kg_m3) {
  std::vector<double> rho;
  for (double x : obs.track.density_kg_m3) {
    if (std::isfinite(x)) rho.push_back(x);
  }
  if (rho.empty()) return std::nullopt;
  std::nth_element(rho.begin(), rho.begin() + static_cast<long>(rho.size() / 2), rho.end());
  const double median = rho[rho.size() / 2];
  if (std::abs(median - nominal.trim_density_kg_m3) <= tolerance_kg_m3) return std::nullopt;
  return median;
}

// A vehicle that cannot fly what the log flew is the wrong vehicle (or a
// broken glider), not a glider with a cause to name: with no steady glide in
// the logged direction at the logged pitch and ballast for most dives or
// most climbs, every "finding" would be the fit straining at the impossible.
void refuse_vehicle_that_cannot_glide(const FlightModel& steady, const Observations& obs) {
  for (const bool diving : {true, false}) {
    std::vector<std::size_t> samples;
    for (std::size_t i = 0; i < obs.size(); ++i) {
      if (obs.diving[i] == diving) samples.push_back(i);
    }
    std::vector<double> rate;
    steady.predict(nominal_values(), false, samples, rate);
    std::size_t flies = 0;
    std::vector<double> ballast;
    for (std::size_t k = 0; k < samples.size(); ++k) {
      if (std::isfinite(rate[k]) && (diving ? rate[k] > 0.0 : rate[k] < 0.0)) ++flies;
      ballast.push_back(obs.ballast_cc[samples[k]]);
    }
    if (samples.empty() || 2 * flies >= samples.size()) continue;
    std::nth_element(ballast.begin(), ballast.begin() + static_cast<long>(ballast.size() / 2), ballast.end());
    char text[400];
    std::snprintf(text, sizeof text,
                  "cannot judge: the vehicle %s cannot %s as this log did: at the logged pitch and ballast (median "
                  "%+.0f cc) it has a steady %s in only %zu of %zu %s samples; is it the right vehicle file "
                  "(--vehicle), or was the glider far out of trim?",
                  steady.vehicle().name.c_str(), diving ? "dive" : "climb", ballast[ballast.size() / 2],
                  diving ? "dive" : "climb", flies, samples.size(), diving ? "steady-dive" : "steady-climb");
    throw CannotJudge(text);
  }
}

// The scored samples of the depth window, split into the yos fitted and
// those held out, and by phase.
struct Split {
  std::vector<std::size_t> all, train, heldout, dives, climbs, turns;
};

Split split_samples(SampleSet& set, const DiagnoseOptions& options) {
  std::erase_if(set.usable, [&](std::size_t i) {
    return !(set.depth_m[i] >= options.window_min_m && set.depth_m[i] <= options.window_max_m);
  });
  if (set.usable.empty()) throw CannotJudge("cannot judge: no scored samples in the depth window");
  Split s;
  s.all = set.usable;
  split_by_yo(s.all, set.yo, s.train, s.heldout);
  if (s.train.empty() || s.heldout.empty()) {
    throw CannotJudge("cannot judge: " + std::to_string(s.train.size()) + " samples in the yos to fit and " +
                      std::to_string(s.heldout.size()) +
                      " in the yos held out (the depth window and the glides leave too few)");
  }
  s.dives = where_phase(set, flightlog::Phase::kDive);
  s.climbs = where_phase(set, flightlog::Phase::kClimb);
  s.turns = where_phase(set, flightlog::Phase::kInflection);
  thin(s.train, options.max_fit_samples);
  thin(s.heldout, options.max_fit_samples);
  return s;
}

// The residuals of `parameters` at every sample of `samples`, by sample index (NaN elsewhere).
std::vector<double> residuals_by_sample(const SampleSet& set, const Parameters& parameters, bool ctd,
                                        const std::vector<std::size_t>& samples) {
  std::vector<double> r_samples;
  residuals(set, parameters, ctd, samples, r_samples);
  std::vector<double> r(set.measured_m_s.size(), kNaN);
  for (std::size_t k = 0; k < samples.size(); ++k) r[samples[k]] = r_samples[k];
  return r;
}

// The nominal model's error: by phase, by depth bin, held out, and the pitch
// where the battery is logged.
void report_baseline(const SampleSet& set, const Split& s, bool dynamic, const Observations& obs,
                     const FlightModel& steady_model, Diagnosis& d) {
  const std::vector<double> r = residuals_by_sample(set, Parameters{}, false, s.all);
  d.baseline.all = rms_where(r, s.all);
  d.baseline.dives = rms_where(r, s.dives);
  d.baseline.climbs = rms_where(r, s.climbs);
  if (dynamic) d.baseline.inflections = rms_where(r, s.turns);
  d.baseline.inflection_samples = dynamic ? s.turns.size() : obs.inflection_samples;
  double max_depth = 0.0;
  for (std::size_t i : s.all) max_depth = std::max(max_depth, set.depth_m[i]);
  const double bin = max_depth > 100.0 ? 25.0 : 10.0;
  for (double from = 0.0; from < max_depth; from += bin) {
    std::vector<std::size_t> in_bin;
    for (std::size_t i : s.all) {
      if (set.depth_m[i] >= from && set.depth_m[i] < from + bin) in_bin.push_back(i);
    }
    if (!in_bin.empty()) d.baseline.by_depth.push_back({from, from + bin, rms_where(r, in_bin)});
  }
  std::vector<double> h;
  residuals(set, Parameters{}, false, s.heldout, h);
  d.baseline.heldout_rms_m_s = rms_of(h);
  if (obs.has_battpos) {
    double sum = 0.0;
    std::size_t n = 0;
    const std::size_t stride = std::max<std::size_t>(1, obs.size() / 400);
    for (std::size_t i = 0; i < obs.size(); i += stride) {
      const double pitch = steady_model.nominal_pitch_rad(i);
      if (!std::isfinite(pitch)) continue;
      sum += (pitch - obs.pitch_rad[i]) * (pitch - obs.pitch_rad[i]);
      ++n;
    }
    if (n > 0) d.baseline.rms_pitch_deg = rad_to_deg(std::sqrt(sum / static_cast<double>(n)));
  }
}

// The candidate effects this log and model can show.
std::vector<Effect> candidate_pool(const Observations& obs, bool dynamic) {
  std::vector<Effect> pool{Effect::kBuoyancyOffset, Effect::kDragChange, Effect::kHullCompressibility,
                           Effect::kVerticalWaterVelocity};
  if (obs.has_temperature) pool.push_back(Effect::kThermalExpansion);
  if (obs.has_ctd) pool.push_back(Effect::kWaterDensity);
  if (dynamic) {
    pool.push_back(Effect::kPumpLag);
    pool.push_back(Effect::kDepthLag);
  }
  pool.push_back(Effect::kLiftChange);
  return pool;
}

// The effects asked for (--fit), fitted jointly with no selection.
void fit_requested(const SampleSet& set, const Split& s, const DiagnoseOptions& options, Candidate& current,
                   FitResult& current_fit, Diagnosis& d) {
  for (Effect e : options.fit_only) {
    if (e == Effect::kWaterDensity) {
      current.ctd_density = true;
    } else {
      current.fitted.push_back(e);
    }
  }
  current_fit = fit_reported(set, current, s.train, s.heldout, options);
  for (Effect e : options.fit_only) d.findings.push_back(new_finding(e, current_fit.heldout_rms, d));
}

// The vertical plane's side of the fitting core's selection
// (fitting_core/stepwise.hpp): the fit of each set of effects, once.
class VerticalSelection : public SelectionProblem {
 public:
  VerticalSelection(const SampleSet& set, const Split& split, const DiagnoseOptions& options, FitResult nominal)
      : set_(set), split_(split), options_(options) {
    fits_.emplace(EffectSet{}, std::move(nominal));
  }
  static Candidate candidate(const EffectSet& effects) {
    Candidate c;
    for (int id : effects) {
      const auto e = static_cast<Effect>(id);
      if (e == Effect::kWaterDensity) {
        c.ctd_density = true;
      } else {
        c.fitted.push_back(e);
      }
    }
    return c;
  }
  FitResult& fitted(const EffectSet& effects) {
    auto it = fits_.find(effects);
    if (it == fits_.end()) {
      it = fits_.emplace(effects, fit_reported(set_, candidate(effects), split_.train, split_.heldout, options_)).first;
    }
    return it->second;
  }
  Score score(const EffectSet& effects) override { return fitted(effects).score(); }
  bool plausible(const EffectSet& effects, int effect) override {
    const auto e = static_cast<Effect>(effect);
    return e == Effect::kWaterDensity ||
           diagnose::plausible(e, fitted(effects).parameters.values[static_cast<std::size_t>(effect)]);
  }
  // The 95 % interval from the joint fit (its Jacobian, once) excludes the nominal.
  bool significant(const EffectSet& effects, int effect) override {
    const auto e = static_cast<Effect>(effect);
    if (e == Effect::kWaterDensity) return true;  // measured, not fitted
    const Candidate c = candidate(effects);
    FitResult& f = fitted(effects);
    add_intervals(set_, c, split_.train, options_.intervals, f);
    const auto j = static_cast<std::size_t>(std::find(c.fitted.begin(), c.fitted.end(), e) - c.fitted.begin());
    return std::abs(f.parameters.values[static_cast<std::size_t>(effect)] - info(e).nominal) > kZ95 * f.sigma[j];
  }

 private:
  const SampleSet& set_;
  const Split& split_;
  const DiagnoseOptions& options_;
  std::map<EffectSet, FitResult> fits_;
};

// The fitting core's forward-then-backward selection (fitting_core/stepwise.hpp;
// the CTD's density a measured input), then the findings ranked by worth,
// each with the held-out error and gain of the model with it and those
// ranked above it. A vertical-velocity depth profile (a parameter per 10 m
// bin) can stand in for any buoyancy that changes with depth, and the
// greedy forward step takes it first when no single physical effect
// explains as much (a hull compressibility comes with a buoyancy offset:
// each alone explains less than the profile, the two together more). So a
// selection whose forward step took the profile must beat the best
// selection without it by the margins any effect must (held-out error and
// BIC); else that selection stands (bench_diagnose_coverage: buoyancy_offset
// + hull_compressibility was read as a profile in 46 % of the logs). Taken,
// the profile may also have kept out an effect and then left in the
// backward step: the selection without it is then the one to compare with.
void select_effects(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                    const std::vector<Effect>& pool, Candidate& current, FitResult& current_fit, Diagnosis& d) {
  VerticalSelection problem(set, s, options, current_fit);
  const auto density = static_cast<int>(Effect::kWaterDensity);
  const SelectionRules rules{options.margins, {density}};
  std::vector<int> candidates;
  for (Effect e : pool) candidates.push_back(static_cast<int>(e));
  // The CTD's density is flown from the start where the log has it: it is a
  // measurement, not a claim, and the margins guard claims. Left to earn its
  // place it could be declined where the model still lacks an offset (the
  // true stratification makes a heavy glider's nominal fit worse), and a
  // negative thermal expansion then stood in for the density and the offset
  // together (docs/science.md, "the CTD's density flown from the start").
  EffectSet start;
  if (std::find(candidates.begin(), candidates.end(), density) != candidates.end()) {
    start.push_back(density);
    candidates = without(candidates, density);
  }
  const EffectSet forward = forward_select(problem, start, candidates, rules);
  std::vector<double> worth;
  EffectSet chosen = backward_eliminate(problem, forward, rules, worth);
  const auto profile = static_cast<int>(Effect::kVerticalWaterVelocity);
  if (std::find(forward.begin(), forward.end(), profile) != forward.end()) {
    std::vector<double> other_worth;
    const EffectSet other = backward_eliminate(
        problem, forward_select(problem, start, without(candidates, profile), rules), rules, other_worth);
    if (!beats(problem.score(chosen), problem.score(other), options.margins)) {
      chosen = other;
      worth = other_worth;
    }
  }
  current = VerticalSelection::candidate(chosen);
  current_fit = problem.fitted(chosen);
  const EffectSet ranked = rank_by_worth(chosen, worth);
  EffectSet so_far;
  for (int e : ranked) {
    so_far.push_back(e);
    const double rms = so_far.size() == ranked.size() ? current_fit.heldout_rms : problem.fitted(so_far).heldout_rms;
    d.findings.push_back(new_finding(static_cast<Effect>(e), rms, d));
  }
}

// The final fit's intervals checked by a replicate: the same effects fitted
// to the held-out yos (from the training fit's values), and each sigma
// widened by the Birge ratio of the two readings (fitting_core::
// replicated_sigma). The intervals from the training yos' Jacobian and
// residuals see noise and errors that differ between glides, not a term the
// model lacks that moves the whole reading: on the independent truth most
// intervals that missed were 1-1.6 of their half-widths off, with counting
// yos instead of glides covering hardly more (docs/science.md, "intervals
// checked by the held-out yos"). Selection is
// unchanged: it judges with the training intervals, as before.
void check_by_heldout_replicate(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                                const Candidate& current, FitResult& current_fit) {
  if (current.fitted.empty() || current_fit.sigma.size() != current.fitted.size()) return;
  FitResult replicate = fit_reported(set, current, s.heldout, s.train, options, &current_fit);
  add_intervals(set, current, s.heldout, options.intervals, replicate);
  if (replicate.sigma.size() != current.fitted.size()) return;
  for (std::size_t j = 0; j < current.fitted.size(); ++j) {
    const auto e = static_cast<std::size_t>(current.fitted[j]);
    double a = current_fit.parameters.values[e], b = replicate.parameters.values[e];
    if (is_lag(current.fitted[j])) a = std::abs(a), b = std::abs(b);  // fitted as |value|
    current_fit.sigma[j] = replicated_sigma(current_fit.sigma[j], a, replicate.sigma[j], b);
  }
}

// The Reynolds prior's own uncertainty in every reading. A diagnosis that
// flies the prior exponent (kDragReynoldsExponentPrior: neither asked for nor
// stated by the vehicle file) reads each effect conditional on it; the truth
// of a glider's skin friction is not known that well, and the drag factor
// that holds at the reference speed then moves with the exponent by
// ln(V / V_ref) per unit of it over the speeds flown - a bias every yo
// shares, which neither the training intervals nor the held-out replicate
// see. Measured on the independent truth (docs/science.md, "Method rule: the
// Reynolds prior's uncertainty in the intervals"): drag_change readings
// -4 % and +3.4 % off with relative half-widths of 2 %, within 1 % with the
// truth's exponent at the prior. The final model is fitted again with the
// exponent one prior sigma higher (kDragReynoldsExponentPriorSigma; one fit)
// and each sigma becomes hypot(sigma, shift). Values and selection are
// unchanged. The refit starts where the reading's own fit started (the
// nominal values, each lag at its grid's best point: the selection's and
// --fit's start), so the shift is the same procedure's answer at two
// exponents. From the final fit's values the optimiser, on a residual that
// is not smooth in the drag, stopped in a nearer, worse minimum (a third of
// the shift the nominal start finds) or walked into another valley the
// reading at the prior is not in (a shift 30 times it) - docs/science.md,
// "The Reynolds prior's refit from the reading's own start".
void add_reynolds_prior_uncertainty(const model::VehicleParams& nominal, const Observations& obs, bool dynamic,
                                    DepthLagForm form, const SampleSet& set, const Split& s,
                                    const DiagnoseOptions& options, const Candidate& current, FitResult& current_fit,
                                    std::vector<double>& shift) {
  shift.assign(current.fitted.size(), 0.0);
  if (current.fitted.empty() || current_fit.sigma.size() != current.fitted.size()) return;
  model::VehicleParams shifted = nominal;
  shifted.hydro.cd0_reynolds_exponent += kDragReynoldsExponentPriorSigma;
  std::optional<FlightModel> steady;
  std::optional<DynamicFlightModel> flown;
  std::optional<DepthLagView> read;
  if (dynamic) {
    flown.emplace(shifted, obs.track, options.max_step_s);
    read.emplace(*flown, form);
  } else {
    steady.emplace(shifted, obs);
  }
  SampleSet other = dynamic ? dynamic_set(*read, obs.track) : steady_set(*steady, obs);
  other.lag_start = set.lag_start;  // each lag starts at the reading's grid point: the grid is not flown again
  const FitResult moved = fit_reported(other, current, s.train, s.heldout, options);
  for (std::size_t j = 0; j < current.fitted.size(); ++j) {
    const auto e = static_cast<std::size_t>(current.fitted[j]);
    double a = current_fit.parameters.values[e], b = moved.parameters.values[e];
    if (is_lag(current.fitted[j])) a = std::abs(a), b = std::abs(b);  // fitted as |value|
    if (!std::isfinite(b)) continue;
    current_fit.sigma[j] = std::hypot(current_fit.sigma[j], b - a);
    shift[j] = b - a;
  }
}

// Every finding's value and 95 % interval from the final joint fit, and the
// extended vehicle's parameters.
void report_final_values(const DepthRateModel& model, const Candidate& current, FitResult& current_fit, Diagnosis& d) {
  for (Finding& finding : d.findings) {
    if (!finding.fitted) {
      finding.value = model.ctd_density_anomaly();
      finding.ci95_low = finding.ci95_high = finding.value;
      continue;
    }
    const auto it = std::find(current.fitted.begin(), current.fitted.end(), finding.effect);
    const std::size_t j = static_cast<std::size_t>(it - current.fitted.begin());
    const std::size_t e = static_cast<std::size_t>(finding.effect);
    finding.value = current_fit.parameters.values[e];
    finding.ci95_low = finding.value - kZ95 * current_fit.sigma[j];
    finding.ci95_high = finding.value + kZ95 * current_fit.sigma[j];
    if (is_lag(finding.effect)) {  // fitted as |value|: report the lag and its interval as such
      finding.value = std::abs(finding.value);
      finding.ci95_low = std::max(0.0, finding.value - kZ95 * current_fit.sigma[j]);
      finding.ci95_high = finding.value + kZ95 * current_fit.sigma[j];
      current_fit.parameters.values[e] = finding.value;
    }
  }
  d.extended = current_fit.parameters.values;
  d.extended_profile = current_fit.parameters.profile;
  d.extended_uses_ctd_density = current.ctd_density;
  if (current.ctd_density) d.extended[static_cast<std::size_t>(Effect::kWaterDensity)] = model.ctd_density_anomaly();
  d.cause = d.findings.empty() ? "none" : info(d.findings.front().effect).id;
}

// What data would tell two effects apart: the physics of why this log could
// not. Pairs not listed get the general answer.
std::string what_separates(Effect a, Effect b) {
  auto is = [&](Effect x, Effect y) { return (a == x && b == y) || (a == y && b == x); };
  auto either = [&](Effect x) { return a == x || b == x; };
  using E = Effect;
  if (is(E::kBuoyancyOffset, E::kVerticalWaterVelocity) || is(E::kBuoyancyOffset, E::kWaterDensity) ||
      is(E::kVerticalWaterVelocity, E::kWaterDensity)) {
    return "dives and climbs with different pumped volumes or pitches (a buoyancy acts through the glide's speed, "
           "water moves the glider whatever its speed), a speed-through-water reference (DVL), or the same water "
           "flown on another day";
  }
  if (either(E::kHullCompressibility) || either(E::kThermalExpansion)) {
    return "glides over a wider range of depths (compressibility) and of temperatures (thermal expansion), or the "
           "same depths flown in other water";
  }
  if (is(E::kDragChange, E::kLiftChange)) {
    return "glides at different pitches (drag acts along the path, lift across it), or a speed-through-water "
           "reference (DVL)";
  }
  if (either(E::kPumpLag) || either(E::kDepthLag)) {
    return "inflections at other pump rates, or the depth from a second clock (a CTD's pressure beside the flight "
           "computer's)";
  }
  return "other flight: different pitches, pumped volumes and depths, or a speed-through-water reference (DVL)";
}

// Identifiability, stated instead of decided silently. For each finding and
// each candidate not taken: their depth-rate signatures (the change of the
// fitted samples' residuals for a step of each, one flight each) with the
// other findings' signatures projected out, and the correlation of the two.
// Where it is high, the candidate is fitted in the finding's place, and the
// pair is reported either way: told apart by the held-out yos, or - if the
// swap explains them within the margins the selection itself uses -
// ambiguous, with both readings and what data would separate them.
// Returns the screened pairs (finding, alternative).
std::vector<ScreenedPair> state_identifiability(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                                                const std::vector<Effect>& pool, const Candidate& current,
                                                const FitResult& current_fit, const FitResult* delay_form_fit,
                                                Diagnosis& d) {
  if (current.fitted.empty()) return {};
  std::vector<double> base;
  residuals(set, current_fit.parameters, current.ctd_density, s.train, base);
  // The signature of `e`: residual change for a step of a tenth of its scale from the fit
  // (a profile steps every bin: a uniform vertical velocity).
  auto signature = [&](int id) {
    const auto e = static_cast<Effect>(id);
    Parameters stepped = current_fit.parameters;
    const double step = 0.1 * info(e).scale;
    stepped.values[static_cast<std::size_t>(e)] += step;
    if (e == Effect::kVerticalWaterVelocity && stepped.profile) {
      for (double& w : stepped.profile->w_m_s) w += step;
    }
    std::vector<double> r;
    residuals(set, stepped, current.ctd_density, s.train, r);
    return signature_column(r, base, step);
  };
  EffectSet chosen;
  for (Effect e : current.fitted) chosen.push_back(static_cast<int>(e));
  std::vector<int> alternatives;
  for (Effect e : pool) {
    if (e != Effect::kWaterDensity) alternatives.push_back(static_cast<int>(e));  // the CTD's, not a fitted number
  }
  const std::vector<ScreenedPair> all = pair_correlations(chosen, alternatives, signature);
  d.screen_correlation = options.ambiguity_screen_correlation;
  for (const ScreenedPair& pair : all) {
    d.screen.push_back({current.fitted[pair.finding], static_cast<Effect>(pair.alternative), pair.correlation});
  }
  const std::vector<ScreenedPair> pairs = screened(all, options.ambiguity_screen_correlation);
  for (const ScreenedPair& pair : pairs) {
    const std::size_t j = pair.finding;
    const Effect effect = current.fitted[j];
    const auto alternative = static_cast<Effect>(pair.alternative);
    const double correlation = pair.correlation;
    Candidate swapped = current;
    swapped.fitted[j] = alternative;
    FitResult f = fit_reported(set, swapped, s.train, s.heldout, options);
    const double value = f.parameters.values[static_cast<std::size_t>(alternative)];
    Ambiguity amb;
    amb.chosen = effect;
    amb.alternative = alternative;
    amb.correlation = correlation;
    amb.alternative_value = is_lag(alternative) ? std::abs(value) : value;
    amb.chosen_heldout_rms_m_s = current_fit.heldout_rms;
    amb.alternative_heldout_rms_m_s = f.heldout_rms;
    amb.score_block_s = options.score_block_s;
    amb.chosen_heldout_score_m_s = current_fit.heldout_score;
    amb.alternative_heldout_score_m_s = f.heldout_score;
    // Within the selection's own margins, on either view of the held-out
    // error, the held-out yos cannot tell them apart.
    amb.ambiguous = indistinguishable(HeldOut{f.heldout_score, f.heldout_rms},
                                      HeldOut{current_fit.heldout_score, current_fit.heldout_rms}, options.margins);
    // A depth lag read as a first-order sensor where the held-out yos do
    // not tell that from a delay: the delay's fit is a reading the log
    // allows too, and an alternative in the lag's place (a fit without the
    // lag, so of no form) that the yos cannot tell from it is not ruled out
    // either (a short pump lag beside the lag: choose_depth_lag_form).
    if (effect == Effect::kDepthLag && delay_form_fit != nullptr) {
      amb.ambiguous =
          amb.ambiguous ||
          indistinguishable(HeldOut{f.heldout_score, f.heldout_rms},
                            HeldOut{delay_form_fit->heldout_score, delay_form_fit->heldout_rms}, options.margins);
    }
    // An implausible alternative is still stated: what rules it out is then
    // the prior (flight_model.cpp's plausible ranges), not this log.
    amb.ruled_out_by_prior = !plausible(alternative, value);
    if (amb.ambiguous) {  // the second reading, with its interval (a Jacobian: only where reported)
      add_intervals(set, swapped, s.train, options.intervals, f);
      amb.alternative_ci95_low = amb.alternative_value - kZ95 * f.sigma[j];
      amb.alternative_ci95_high = amb.alternative_value + kZ95 * f.sigma[j];
      if (is_lag(alternative)) amb.alternative_ci95_low = std::max(0.0, amb.alternative_ci95_low);
      amb.separate = what_separates(effect, alternative);
    }
    d.ambiguities.push_back(std::move(amb));
  }
  return pairs;
}

// The selected effects with `alternative` fitted beside them, from the
// selected fit (the candidate from its nominal): a step from it, not a search
// from the nominal vehicle. Once per alternative: hold_aliased_readings and
// read_unnamed_volume_terms share it.
using BesideFits = std::map<Effect, FitResult>;
FitResult& fit_beside(const SampleSet& set, const Split& s, const DiagnoseOptions& options, const Candidate& current,
                      const FitResult& current_fit, Effect alternative, BesideFits& fits) {
  auto it = fits.find(alternative);
  if (it == fits.end()) {
    Candidate joint = current;
    joint.fitted.push_back(alternative);
    it = fits.emplace(alternative, fit_reported(set, joint, s.train, s.heldout, options, &current_fit)).first;
  }
  return it->second;
}

// A finding's 95 % interval is conditional on the effects selected. A
// candidate the margins declined can still be there - a hull compressibility
// too small to cut the held-out error by the margins, beside the buoyancy
// offset whose signature it shares - and then it moves the finding by more
// than the finding's own interval: of the intervals that missed the truth on
// the independent truth benchmark, most were of a finding whose hidden
// partner was not named (docs/science.md). So where a finding and a
// candidate not taken alias (the identifiability screen's pairs), both are
// fitted together; where that joint fit says the candidate is there (its own
// interval excludes "no effect", both values plausible), the finding's
// interval also holds the finding's reading in the joint fit (the readings
// weighed alike, at the end). Where the
// joint fit cannot see the candidate and the held-out yos prefer it by the
// selection's margins (both views of their error), the partner is there by
// the yos, at a size this log cannot read (its interval holds "no effect"):
// the pair is stated ambiguous with both readings (the finding alone, and the
// finding with the partner beside it), and the finding's interval holds the
// second. Where the held-out yos predict the joint fit no worse (both views)
// but by less than the margins, the log has not ruled the partner out either
// and the interval holds the joint reading without the statement; only a
// partner the held-out yos reject leaves the conditional interval (a lift
// beside a drag on deep logs moves the held-out RMS by under 1 %: the drag
// read alone missed its truth by 1-6 half-widths in 9 of 32 draws;
// docs/science.md, "Where the vertical plane's intervals miss").
// On the independent truth a hidden vertical water velocity the selection
// did not name is the case: the offset read alone absorbs it (7-26 g off
// where this fired on a validation seed, most intervals missing the truth;
// docs/science.md, "The buoyancy offset beside a partner this log cannot
// size").
void hold_aliased_readings(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                           const Candidate& current, const FitResult& current_fit,
                           const std::vector<ScreenedPair>& pairs, BesideFits& fits, Diagnosis& d) {
  std::vector<int> tried;
  std::map<Effect, std::vector<std::pair<double, double>>> held;  // per finding: (value, sigma) held beside
  for (const ScreenedPair& screened : pairs) {
    if (std::find(tried.begin(), tried.end(), screened.alternative) != tried.end()) continue;
    tried.push_back(screened.alternative);
    const auto alternative = static_cast<Effect>(screened.alternative);
    Candidate joint = current;
    joint.fitted.push_back(alternative);
    FitResult& f = fit_beside(set, s, options, current, current_fit, alternative, fits);
    const double seen = f.parameters.values[static_cast<std::size_t>(alternative)];
    if (!plausible(alternative, seen)) continue;
    add_intervals(set, joint, s.train, options.intervals, f);
    const bool is_seen = std::abs(seen - info(alternative).nominal) > kZ95 * f.sigma.back();
    for (const ScreenedPair& pair : pairs) {
      if (pair.alternative != screened.alternative) continue;
      const Effect effect = current.fitted[pair.finding];
      const auto finding = std::find_if(d.findings.begin(), d.findings.end(),
                                        [&](const Finding& x) { return x.fitted && x.effect == effect; });
      if (finding == d.findings.end()) continue;
      const double raw = f.parameters.values[static_cast<std::size_t>(effect)];
      if (!plausible(effect, raw)) continue;  // a reading the prior rules out (flight_model.cpp's ranges)
      const double value = is_lag(effect) ? std::abs(raw) : raw;
      const double half = kZ95 * f.sigma[pair.finding];
      const double low = is_lag(effect) ? std::max(0.0, value - half) : value - half;
      BesideReading r;
      r.finding = effect;
      r.partner = alternative;
      r.correlation = pair.correlation;
      r.finding_value = value;
      r.finding_ci95_low = low;
      r.finding_ci95_high = value + half;
      r.partner_value = seen;
      r.partner_ci95_low = seen - kZ95 * f.sigma.back();
      r.partner_ci95_high = seen + kZ95 * f.sigma.back();
      r.heldout_rms_m_s = f.heldout_rms;
      r.heldout_score_m_s = f.heldout_score;
      r.chosen_heldout_rms_m_s = current_fit.heldout_rms;
      r.chosen_heldout_score_m_s = current_fit.heldout_score;
      r.seen = is_seen;
      r.ambiguous = !is_seen && improves_heldout(f.heldout_score, current_fit.heldout_score, options.margins) &&
                    improves_heldout(f.heldout_rms, current_fit.heldout_rms, options.margins);
      if (r.ambiguous) r.separate = what_separates(effect, alternative);
      d.beside.push_back(r);
      // Not seen, not preferred, and not rejected by the held-out yos either.
      const bool not_rejected =
          f.heldout_score <= current_fit.heldout_score && f.heldout_rms <= current_fit.heldout_rms;
      if (!is_seen && !r.ambiguous && !not_rejected) continue;
      held[effect].push_back({value, f.sigma[pair.finding]});
      finding->interval_holds_with.push_back(alternative);
    }
  }
  // The interval holds the central 95 % of the readings weighed alike (the
  // conditional one and each held beside; fitting_core::mixture_interval),
  // not the union of their 95 % intervals: where the held-out yos cannot
  // choose between the models, each keeps its share of the tails, not all of
  // them (on two fresh design seeds the mixture kept the 10 misses the union
  // covered, 45 of its 48 widened intervals narrower, x0.73-1.00;
  // docs/science.md, "The readings beside a finding weighed alike"). Never
  // narrower than the conditional interval.
  for (const auto& [effect, readings] : held) {
    Finding& finding = *std::find_if(d.findings.begin(), d.findings.end(),
                                     [&](const Finding& x) { return x.fitted && x.effect == effect; });
    const auto j = static_cast<std::size_t>(std::find(current.fitted.begin(), current.fitted.end(), effect) -
                                            current.fitted.begin());
    std::vector<double> means{finding.value}, sigmas{current_fit.sigma[j]};
    for (const auto& [mean, sigma] : readings) {
      means.push_back(mean);
      sigmas.push_back(sigma);
    }
    const fitting_core::Estimate m = fitting_core::mixture_interval(means, sigmas);
    finding.ci95_low = std::min(finding.ci95_low, is_lag(effect) ? std::max(0.0, m.low) : m.low);
    finding.ci95_high = std::max(finding.ci95_high, m.high);
  }
}

// The unnamed volume terms fitted beside the selected effects, both at once
// where both are unnamed (their signatures on a yo nearly coincide where the
// water cools with depth, so one read alone takes the other's share: a
// hidden compressibility read as an expansion "seen" beside the findings),
// each sigma checked by the held-out yos as the findings' are
// (check_by_heldout_replicate): beside a partner the selection missed (a
// water velocity) the training interval alone put a term not there 2 sigma
// from zero in 12 of 93 logs. A sigma is NaN where no reading is plausible
// (only the prior rules it out: no interval is fitted for it).
struct VolumeTermsBeside {
  std::vector<Effect> unnamed;
  FitResult fit;
  std::vector<double> sigma;  // per unnamed term
  bool read = false;          // false: the intervals could not be fitted
};

VolumeTermsBeside read_volume_terms_beside(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                                           const std::vector<Effect>& pool, const Candidate& current,
                                           const FitResult& current_fit, BesideFits& fits) {
  VolumeTermsBeside b;
  for (const Effect e : {Effect::kHullCompressibility, Effect::kThermalExpansion}) {
    if (std::find(pool.begin(), pool.end(), e) == pool.end()) continue;                                // no temperature
    if (std::find(current.fitted.begin(), current.fitted.end(), e) != current.fitted.end()) continue;  // named
    b.unnamed.push_back(e);
  }
  if (b.unnamed.empty()) return b;
  Candidate joint = current;
  joint.fitted.insert(joint.fitted.end(), b.unnamed.begin(), b.unnamed.end());
  b.fit = b.unnamed.size() > 1 ? fit_reported(set, joint, s.train, s.heldout, options, &current_fit)
                               : fit_beside(set, s, options, current, current_fit, b.unnamed.front(), fits);
  const auto value_of = [&](Effect e) { return b.fit.parameters.values[static_cast<std::size_t>(e)]; };
  b.sigma.assign(b.unnamed.size(), kNaN);
  b.read = true;
  if (std::none_of(b.unnamed.begin(), b.unnamed.end(), [&](Effect e) { return plausible(e, value_of(e)); })) return b;
  add_intervals(set, joint, s.train, options.intervals, b.fit);
  FitResult replicate = fit_reported(set, joint, s.heldout, s.train, options, &b.fit);
  add_intervals(set, joint, s.heldout, options.intervals, replicate);
  if (b.fit.sigma.size() != joint.fitted.size() || replicate.sigma.size() != joint.fitted.size()) {
    b.read = false;
    return b;
  }
  for (std::size_t k = 0; k < b.unnamed.size(); ++k) {
    const std::size_t j = current.fitted.size() + k;
    const auto e = static_cast<std::size_t>(b.unnamed[k]);
    b.sigma[k] = replicated_sigma(b.fit.sigma[j], b.fit.parameters.values[e], replicate.sigma[j],
                                  replicate.parameters.values[e]);
  }
  return b;
}

// A thermal expansion the selection's margins declined, named where the log
// sees it: read beside the selected effects (read_volume_terms_beside: with
// an unnamed compressibility beside it, its interval checked by the held-out
// yos), plausible, at least the minimum detectable effect from none
// (kZDetectable sigmas: what benchmarks/identifiability.py calls
// identifiable), and of the sign a hull has (the vehicle file's expansion
// with it is positive: a hull grows as it warms). Over the independent
// truth's 5-10 K an expansion of 1-7e-5 /K moves the depth rate by a few
// mm/s over whole glides, at the depth sensor's noise in the held-out RMS:
// the margins (3 %, 0.5 mm/s) declined expansions read 4-7 sigma from zero
// (the training interval widened by the held-out replicate), within 15 % of
// the truth in most (docs/science.md, "A thermal expansion the log sees,
// named"). The sign:
// a negative expansion beside the findings stands in for an unnamed water
// velocity (the velocity's profile, warm water above, read as a hull that
// shrinks as it warms). Ranked last, as the depth lag beside a pump lag;
// every later rule (intervals, aliases, statements) sees it as selected.
void name_seen_thermal_expansion(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                                 const std::vector<Effect>& pool, double vehicle_expansion_per_k, Candidate& current,
                                 FitResult& current_fit, Diagnosis& d) {
  BesideFits fits;  // of the selected set as it is here, not shared with the later readings
  const VolumeTermsBeside b = read_volume_terms_beside(set, s, options, pool, current, current_fit, fits);
  const auto it = std::find(b.unnamed.begin(), b.unnamed.end(), Effect::kThermalExpansion);
  if (!b.read || it == b.unnamed.end()) return;
  const double value = b.fit.parameters.values[static_cast<std::size_t>(Effect::kThermalExpansion)];
  const double sigma = b.sigma[static_cast<std::size_t>(it - b.unnamed.begin())];
  if (!plausible(Effect::kThermalExpansion, value) || !(std::abs(value) >= kZDetectable * sigma) ||
      !(vehicle_expansion_per_k + value > 0.0)) {
    return;
  }
  Candidate joint = current;
  joint.fitted.push_back(Effect::kThermalExpansion);
  FitResult f = fit_reported(set, joint, s.train, s.heldout, options, &current_fit);
  d.findings.push_back(new_finding(Effect::kThermalExpansion, f.heldout_rms, d));
  current = std::move(joint);
  current_fit = std::move(f);
}

// The hull's volume terms the selection did not name, each read beside the
// findings and stated (Diagnosis::unnamed). Their signature on a yo is a
// buoyancy that grows with depth or with the water's cooling: over the
// independent truth's 40-180 m and 5-10 K a compressibility of 0.5-3e-10 /Pa
// or an expansion of 1-7e-5 /K moves the depth rate by a few mm/s over whole
// glides, at the depth sensor's noise in the held-out RMS (the margins
// decline them) while the training fit's interval can see them (an
// expansion's) or cannot (most compressibilities: forced-fit z median ~1.5).
// Unnamed, the diagnosis said nothing, which reads as "none": the reading
// beside the findings says how large a term this log shows or cannot rule
// out. A statement, not a finding: values, selection and intervals are
// unchanged (docs/science.md, "The hull's volume terms where not named").
void read_unnamed_volume_terms(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                               const std::vector<Effect>& pool, const Candidate& current, const FitResult& current_fit,
                               BesideFits& fits, Diagnosis& d) {
  const VolumeTermsBeside b = read_volume_terms_beside(set, s, options, pool, current, current_fit, fits);
  if (!b.read) return;
  for (std::size_t k = 0; k < b.unnamed.size(); ++k) {
    const Effect e = b.unnamed[k];
    UnnamedReading r;
    r.effect = e;
    r.value = b.fit.parameters.values[static_cast<std::size_t>(e)];
    r.ruled_out_by_prior = !plausible(e, r.value);
    r.ci95_low = r.ruled_out_by_prior ? kNaN : r.value - kZ95 * b.sigma[k];
    r.ci95_high = r.ruled_out_by_prior ? kNaN : r.value + kZ95 * b.sigma[k];
    r.heldout_rms_m_s = b.fit.heldout_rms;
    r.heldout_score_m_s = b.fit.heldout_score;
    r.chosen_heldout_rms_m_s = current_fit.heldout_rms;
    r.chosen_heldout_score_m_s = current_fit.heldout_score;
    r.seen = !r.ruled_out_by_prior && std::abs(r.value - info(e).nominal) > kZ95 * b.sigma[k];
    r.separate = what_separates(e, e);
    d.unnamed.push_back(std::move(r));
  }
}

// The pump lag read with the pressure sensor's delay fitted beside it
// (docs/science.md, "Method rule: the pump lag beside the sensor's delay").
// A pump lag shows only at the inflections, where a depth read late also
// looks like a pump acting late - but the pitch, logged on time, carries part
// of the inflection's timing, so a pump lag fitted alone reads a sensor's
// delay about twice over (independent truth: a hidden depth lag of 0.5, 1
// and 2 s read pump lags of 1.2, 2.5 and 4.0 s on a log with none; its own
// 0.1-0.5 s pressure-sensor lag up to 1.9 s). A delay that small rarely
// earns a finding of its own, so where the selection names a pump lag and
// no depth lag, the pump lag's value and interval are those of the joint
// fit, where it predicts the held-out yos no worse: the depth lag a
// nuisance (in the extended vehicle, not a finding).
// Not where the depth lag was screened as the pump lag's alias: its
// interval then already holds that joint reading.
// The depth lag fitted so is named (a finding, ranked last) where its
// training interval puts it at least the minimum detectable effect from no
// lag (kZDetectable sigmas: what benchmarks/identifiability.py calls
// identifiable): the selection's margins judge it against the pump lag
// alone, which already reads much of the sensor's delay, so a lag the joint
// fit sizes well earned no step of its own (docs/science.md, "Method rule:
// a depth lag beside a named pump lag").
// The pump lag as the selection read it, alone (no depth lag beside): its
// value, training sigma and held-out errors, for hold_traded_lag.
struct LagReadAlone {
  double value = 0.0, sigma = 0.0;
  HeldOut heldout;
};

void read_pump_lag_beside_depth_lag(const SampleSet& set, const Split& s, const DiagnoseOptions& options,
                                    const std::vector<ScreenedPair>& aliases, Candidate& current,
                                    FitResult& current_fit, std::optional<LagReadAlone>& alone, Diagnosis& d) {
  const auto fitted = [&](Effect e) {
    return std::find(current.fitted.begin(), current.fitted.end(), e) != current.fitted.end();
  };
  const auto depth_lag = static_cast<int>(Effect::kDepthLag);
  if (!fitted(Effect::kPumpLag) || fitted(Effect::kDepthLag) ||
      std::any_of(aliases.begin(), aliases.end(), [&](const ScreenedPair& a) { return a.alternative == depth_lag; })) {
    return;
  }
  // The depth lag starts at the best point of its grid at the selected fit
  // (a conditional profile; a depth lag reuses the flight, so its 11 points
  // fly once). Not from its nominal grid (lag_grid_start): that is where a
  // depth lag alone best stands in for a pump lag (both lags from their
  // nominal grids, `--fit water_density,pump_lag,depth_lag` read an 8.1 s
  // pump lag as 2.3 s beside a 1.1 s depth lag).
  const auto index = static_cast<std::size_t>(Effect::kDepthLag);
  const DelayGrid grid = lag_grid(Effect::kDepthLag);
  const double best = best_on_grid(grid, rss_on_grid(grid, [&](double lag) {
                                     Parameters x = current_fit.parameters;
                                     x.values[index] = lag;
                                     return train_rss_at(set, x, current.ctd_density, s.train);
                                   }));
  FitResult from = current_fit;
  from.parameters.values[index] = best > 0.0 ? best : 0.2 * info(Effect::kDepthLag).scale;  // as fit()'s start at 0
  Candidate joint = current;
  joint.fitted.push_back(Effect::kDepthLag);
  FitResult f = fit_reported(set, joint, s.train, s.heldout, options, &from);
  double& lag = f.parameters.values[index];
  lag = std::abs(lag);  // fitted as |value|, as every lag
  // Not where the delay beside it predicts the held-out yos worse (the
  // selection's own score): the data do not carry it there (fresh truth
  // draws: a 4.76 s lag beside a drag change read 1.72 s, an 8.73 s lag
  // alone 3.76 s; docs/science.md).
  if (!plausible(Effect::kDepthLag, lag) || f.heldout_score > current_fit.heldout_score) return;
  add_intervals(set, joint, s.train, options.intervals, f);
  if (lag >= kZDetectable * f.sigma.back()) d.findings.push_back(new_finding(Effect::kDepthLag, f.heldout_rms, d));
  const auto j = static_cast<std::size_t>(std::find(current.fitted.begin(), current.fitted.end(), Effect::kPumpLag) -
                                          current.fitted.begin());
  if (j < current_fit.sigma.size()) {
    alone = LagReadAlone{std::abs(current_fit.parameters.values[static_cast<std::size_t>(Effect::kPumpLag)]),
                         current_fit.sigma[j], HeldOut{current_fit.heldout_score, current_fit.heldout_rms}};
  }
  current = std::move(joint);
  current_fit = std::move(f);
}

// The pump lag and the depth lag trade at the inflections, the only place
// either shows: a depth read late looks like a pump acting late, and their
// joint fit slides along a curved valley whose Jacobian interval sees only
// its local slope (independent truth, deep logs: a 20.4 s pump lag read
// 21.3 s [19.0, 23.5] alone and 15.2 s [11.8, 18.6] beside a 1.2 s depth lag
// the truth's 0.3 s sensor does not have, the held-out RMS 0.23 % apart; a
// 2.21 s sensor lag read 2.97 s [2.63, 3.29] alone and 2.75 s beside a 1.9 s
// pump lag (truth 5.3 s), 0.14 % apart; docs/science.md, "The pump lag and
// the depth lag traded"). Where one lag is named and the held-out yos cannot
// tell the model with the other beside it from the model without it
// (fitting_core::indistinguishable: the selection's margins, either view -
// the ambiguity statement's test), the log has not said which of the two
// readings is the lag's: the finding's interval holds both, weighed alike
// (fitting_core::mixture_interval, as hold_aliased_readings), and the pair is
// stated (`read_beside`, ambiguous, what would separate them). Values,
// findings and selection are unchanged.
// - A pump lag named with the depth lag fitted beside it
//   (read_pump_lag_beside_depth_lag): the other reading is the pump lag
//   alone (`alone`, the selection's fit; its training sigma).
// - A depth lag named, no pump lag fitted: the pump lag is fitted beside it
//   (fit_beside, shared with hold_aliased_readings) and the depth lag's
//   reading there is the other.
void hold_traded_lag(const SampleSet& set, const Split& s, const DiagnoseOptions& options, const Candidate& current,
                     const FitResult& current_fit, const std::optional<LagReadAlone>& alone, BesideFits& fits,
                     Diagnosis& d) {
  const auto index_of = [&](Effect e) {
    return static_cast<std::size_t>(std::find(current.fitted.begin(), current.fitted.end(), e) -
                                    current.fitted.begin());
  };
  const auto named = [&](Effect e) {
    return std::find_if(d.findings.begin(), d.findings.end(),
                        [&](const Finding& x) { return x.fitted && x.effect == e; });
  };
  const HeldOut selected{current_fit.heldout_score, current_fit.heldout_rms};
  // The finding's interval holds the other reading: the mixture of the two,
  // never narrower than what it holds already.
  const auto hold = [&](Finding& finding, double other, double other_sigma, Effect partner) {
    const std::size_t j = index_of(finding.effect);
    if (j >= current_fit.sigma.size() || !std::isfinite(other) || !std::isfinite(other_sigma)) return;
    const std::array<double, 2> means{finding.value, other}, sigmas{current_fit.sigma[j], other_sigma};
    const fitting_core::Estimate m = fitting_core::mixture_interval(means, sigmas);
    finding.ci95_low = std::min(finding.ci95_low, std::max(0.0, m.low));
    finding.ci95_high = std::max(finding.ci95_high, m.high);
    if (std::find(finding.interval_holds_with.begin(), finding.interval_holds_with.end(), partner) ==
        finding.interval_holds_with.end()) {
      finding.interval_holds_with.push_back(partner);
    }
  };
  const auto state = [&](Effect finding, Effect partner, double finding_value, double finding_sigma,
                         double partner_value, double partner_sigma, const HeldOut& with, const HeldOut& without) {
    const bool stated = std::any_of(d.beside.begin(), d.beside.end(), [&](const BesideReading& b) {
      return b.finding == finding && b.partner == partner;
    });
    if (stated) return;
    BesideReading r;
    r.finding = finding;
    r.partner = partner;
    for (const Diagnosis::ScreenedCorrelation& c : d.screen) {  // the screen's, where it paired them
      if (c.chosen == finding && c.alternative == partner) r.correlation = c.correlation;
    }
    r.finding_value = finding_value;
    r.finding_ci95_low = std::max(0.0, finding_value - kZ95 * finding_sigma);
    r.finding_ci95_high = finding_value + kZ95 * finding_sigma;
    r.partner_value = partner_value;
    r.partner_ci95_low = std::max(0.0, partner_value - kZ95 * partner_sigma);
    r.partner_ci95_high = partner_value + kZ95 * partner_sigma;
    r.heldout_rms_m_s = with.rms;
    r.heldout_score_m_s = with.score;
    r.chosen_heldout_rms_m_s = without.rms;
    r.chosen_heldout_score_m_s = without.score;
    r.seen = partner_value > kZ95 * partner_sigma;
    r.ambiguous = true;
    r.lags_traded = true;
    r.separate = what_separates(finding, partner);
    d.beside.push_back(r);
  };
  const auto pump = named(Effect::kPumpLag);
  if (alone && pump != d.findings.end() && indistinguishable(alone->heldout, selected, options.margins)) {
    if (index_of(Effect::kDepthLag) < current_fit.sigma.size()) {
      // Stated as the pump lag read with the depth lag at none beside it
      // (partner 0 s), the model the selection chose before.
      hold(*pump, alone->value, alone->sigma, Effect::kDepthLag);
      state(Effect::kPumpLag, Effect::kDepthLag, alone->value, alone->sigma, 0.0, 0.0, alone->heldout, selected);
    }
  }
  const auto depth = named(Effect::kDepthLag);
  if (depth == d.findings.end() || index_of(Effect::kPumpLag) < current.fitted.size()) return;
  FitResult& f = fit_beside(set, s, options, current, current_fit, Effect::kPumpLag, fits);
  const double lag = std::abs(f.parameters.values[static_cast<std::size_t>(Effect::kPumpLag)]);
  const double other = std::abs(f.parameters.values[static_cast<std::size_t>(Effect::kDepthLag)]);
  const HeldOut beside{f.heldout_score, f.heldout_rms};
  if (!plausible(Effect::kPumpLag, lag) || !indistinguishable(beside, selected, options.margins)) return;
  Candidate joint = current;
  joint.fitted.push_back(Effect::kPumpLag);
  if (f.sigma.size() != joint.fitted.size()) add_intervals(set, joint, s.train, options.intervals, f);
  if (f.sigma.size() != joint.fitted.size()) return;
  const std::size_t k = index_of(Effect::kDepthLag);
  hold(*depth, other, f.sigma[k], Effect::kPumpLag);
  state(Effect::kDepthLag, Effect::kPumpLag, other, f.sigma[k], lag, f.sigma.back(), beside, selected);
}

// The depth lag in the form the held-out yos prefer (depth_lag.hpp). The
// selection runs with the delay; where the final model fits a depth lag, the
// same effects are fitted again with it a first-order sensor (`sensed`: the
// same flights read through the other form), from the delay's fit, and that
// fit is taken where it predicts the held-out yos better (the selection's
// score). Only the form of a lag already selected is chosen, never whether
// there is one: a first-order lag smooths a turn as a short pump lag does,
// and flown through the selection it read two 7 s pump lags beside a depth
// lag as one 4-5.5 s depth lag (docs/science.md, session 40 vtherm); a
// delay fits a science computer's late time stamps better than a sensor
// (gliderflight-adcp's held-out RMS 10.77 -> 10.99 mm/s as a sensor).
// Returns true where the first-order form is taken (current_fit is then its
// fit); `tied_delay` then keeps the delay's fit where the two forms tie.
bool choose_depth_lag_form(const SampleSet& sensed, const Split& s, const DiagnoseOptions& options,
                           const Candidate& current, FitResult& current_fit, std::optional<FitResult>& tied_delay,
                           Diagnosis& d) {
  if (std::find(current.fitted.begin(), current.fitted.end(), Effect::kDepthLag) == current.fitted.end()) return false;
  const auto index = static_cast<std::size_t>(Effect::kDepthLag);
  FitResult f = fit_reported(sensed, current, s.train, s.heldout, options, &current_fit);
  DepthLagFormChoice choice;
  choice.delay_s = std::abs(current_fit.parameters.values[index]);
  choice.first_order_s = std::abs(f.parameters.values[index]);
  choice.delay_heldout_score_m_s = current_fit.heldout_score;
  choice.first_order_heldout_score_m_s = f.heldout_score;
  choice.delay_heldout_rms_m_s = current_fit.heldout_rms;
  choice.first_order_heldout_rms_m_s = f.heldout_rms;
  choice.told_apart = !indistinguishable(HeldOut{f.heldout_score, f.heldout_rms},
                                         HeldOut{current_fit.heldout_score, current_fit.heldout_rms}, options.margins);
  const bool sensor = plausible(Effect::kDepthLag, choice.first_order_s) && f.heldout_score < current_fit.heldout_score;
  if (sensor) {
    choice.form = DepthLagForm::kFirstOrder;
    for (Finding& finding : d.findings) {  // those that reported the selected model's error (its last rank)
      if (finding.heldout_rms_m_s != current_fit.heldout_rms) continue;
      finding.heldout_rms_m_s = f.heldout_rms;
      finding.gain = 1.0 - f.heldout_rms / d.baseline.heldout_rms_m_s;
    }
    if (!choice.told_apart) tied_delay = current_fit;
    current_fit = std::move(f);
  }
  d.depth_lag_form = choice;
  return sensor;
}

// Where the held-out yos do not tell the depth lag's two forms apart, the
// log does not say which lag it has: the interval also holds the other
// form's reading, with the width of its own (the same data and effects; its
// own Jacobian is not flown). ci95_conditional keeps the chosen form's.
void hold_other_depth_lag_form(Diagnosis& d) {
  if (!d.depth_lag_form || d.depth_lag_form->told_apart) return;
  const DepthLagFormChoice& c = *d.depth_lag_form;
  const double other = c.form == DepthLagForm::kFirstOrder ? c.delay_s : c.first_order_s;
  for (Finding& f : d.findings) {
    if (f.effect != Effect::kDepthLag || !f.fitted) continue;
    f.ci95_low = std::max(0.0, std::min(f.ci95_low, other - (f.value - f.ci95_low)));
    f.ci95_high = std::max(f.ci95_high, other + (f.ci95_high - f.value));
  }
}

// A lift whose interval reaches the lifts where the glides flown get a
// stalled steady state (stall_branch.hpp): there the dynamic model's misfit
// jumps wherever one glide changes branch, and the interval from its local
// slope is that of one tooth. The interval then spans those onsets too:
// within them the data say the glides are near the stall, not which lift.
void widen_lift_at_stall(const model::VehicleParams& nominal, const Track& track, Diagnosis& d) {
  constexpr double kSteadyPitchRate = 0.01;  // rad/s: a glide's, not an inflection's (~0.03)
  for (Finding& finding : d.findings) {
    if (finding.effect != Effect::kLiftChange || !finding.fitted) continue;
    std::vector<double> pitch;
    pitch.reserve(track.scored.size());
    for (std::size_t k : track.scored) {
      if (std::abs(track.pitch_slope_rad_s[k]) < kSteadyPitchRate) pitch.push_back(track.pitch_rad[k]);
    }
    const LiftBand band = stall_onset_band(nominal, d.extended, pitch);
    if (band.high <= 0.0 || finding.ci95_high < band.low || finding.ci95_low > band.high) continue;
    finding.ci95_low = std::min(finding.ci95_low, band.low);
    finding.ci95_high = std::max(finding.ci95_high, band.high);
  }
}

// The pitch trim, last and on the steady glides: it is judged with the
// depth-rate effects already found.
void diagnose_pitch_trim_last(const FlightModel& steady_model, const Observations& obs, const DiagnoseOptions& options,
                              Diagnosis& d) {
  std::vector<std::size_t> steady_samples(obs.size()), steady_train, steady_heldout;
  std::iota(steady_samples.begin(), steady_samples.end(), std::size_t{0});
  split_by_yo(steady_samples, obs.yo, steady_train, steady_heldout);
  thin(steady_train, options.max_fit_samples);
  thin(steady_heldout, options.max_fit_samples);
  diagnose_pitch_trim(steady_model, obs, steady_train, steady_heldout, options, d);
  if (d.cause == "none" && !d.findings.empty()) d.cause = info(d.findings.front().effect).id;
}

}  // namespace

const char* to_string(FlightModelKind kind) { return kind == FlightModelKind::kDynamic ? "dynamic" : "steady"; }

// The nominal model's error, the effects that explain it (selected or asked
// for), their values from the final joint fit, the gain on held-out yos, the
// speed through water where a DVL measured it, and the pitch trim.
Diagnosis diagnose(const model::VehicleParams& given, const Observations& obs, const DiagnoseOptions& options) {
  Diagnosis d;
  d.vehicle = given.name;
  d.thermal_reference_c = obs.track.median_temperature_c;
  model::VehicleParams nominal = given;
  nominal.hydro.cd0_reynolds_exponent = drag_reynolds_exponent_for(given, options.drag_reynolds_exponent);
  d.drag_reynolds_exponent = nominal.hydro.cd0_reynolds_exponent;
  d.drag_reference_speed_m_s = nominal.hydro.cd0_reference_speed_m_s;
  if (const auto rho = retrim_density(given, obs, options.retrim_tolerance_kg_m3)) {
    d.retrimmed_from_kg_m3 = given.trim_density_kg_m3;
    nominal.trim_density_kg_m3 = *rho;
    d.retrimmed_to_kg_m3 = *rho;
  }
  const FlightModel steady_model(nominal, obs);
  refuse_vehicle_that_cannot_glide(steady_model, obs);
  const DynamicFlightModel dynamic_model(nominal, obs.track, options.max_step_s);
  const DepthLagView delayed(dynamic_model, DepthLagForm::kDelay), sensed(dynamic_model, DepthLagForm::kFirstOrder);
  const bool dynamic = options.model == FlightModelKind::kDynamic && !obs.track.scored.empty();
  d.model = dynamic ? FlightModelKind::kDynamic : FlightModelKind::kSteady;
  SampleSet delay_set = dynamic ? dynamic_set(delayed, obs.track) : steady_set(steady_model, obs);
  const Split s = split_samples(delay_set, options);
  d.samples_used = s.all.size();
  d.train_samples = s.train.size();
  d.heldout_samples = s.heldout.size();

  report_baseline(delay_set, s, dynamic, obs, steady_model, d);

  const std::vector<Effect> pool = candidate_pool(obs, dynamic);
  for (Effect e : pool) d.candidates_tried.emplace_back(info(e).id);
  Candidate current;
  FitResult current_fit = fit_reported(delay_set, current, s.train, s.heldout, options);
  if (options.fit_only.empty()) {
    select_effects(delay_set, s, options, pool, current, current_fit, d);
  } else {
    fit_requested(delay_set, s, options, current, current_fit, d);
  }
  // From here on, the depth lag in the form the held-out yos prefer.
  SampleSet sensor_set = dynamic_set(sensed, obs.track);
  sensor_set.usable = delay_set.usable;        // the depth window's (split_samples)
  sensor_set.lag_start = delay_set.lag_start;  // each fit from here starts at the selected fit's values
  std::optional<FitResult> tied_delay;
  const bool sensor = dynamic && choose_depth_lag_form(sensor_set, s, options, current, current_fit, tied_delay, d);
  const SampleSet& set = sensor ? sensor_set : delay_set;
  if (options.fit_only.empty())
    name_seen_thermal_expansion(set, s, options, pool, nominal.hull_thermal_expansion_per_k, current, current_fit, d);
  add_intervals(set, current, s.train, options.intervals, current_fit);
  std::vector<ScreenedPair> aliases;
  if (options.fit_only.empty()) {
    aliases =
        state_identifiability(set, s, options, pool, current, current_fit, tied_delay ? &*tied_delay : nullptr, d);
  }
  std::optional<LagReadAlone> pump_lag_alone;
  if (options.fit_only.empty() && dynamic)
    read_pump_lag_beside_depth_lag(set, s, options, aliases, current, current_fit, pump_lag_alone, d);
  check_by_heldout_replicate(set, s, options, current, current_fit);
  std::vector<double> prior_shift;
  if (flies_reynolds_prior(given, options.drag_reynolds_exponent)) {
    d.drag_reynolds_exponent_sigma = kDragReynoldsExponentPriorSigma;
    add_reynolds_prior_uncertainty(nominal, obs, dynamic, sensor ? DepthLagForm::kFirstOrder : DepthLagForm::kDelay,
                                   set, s, options, current, current_fit, prior_shift);
  }
  report_final_values(set.model, current, current_fit, d);
  for (Finding& f : d.findings) {
    f.ci95_conditional_low = f.ci95_low;
    f.ci95_conditional_high = f.ci95_high;
    const auto it = std::find(current.fitted.begin(), current.fitted.end(), f.effect);
    const auto j = static_cast<std::size_t>(it - current.fitted.begin());
    if (f.fitted && j < prior_shift.size()) f.reynolds_prior_shift = prior_shift[j];
  }
  BesideFits beside_fits;
  hold_aliased_readings(set, s, options, current, current_fit, aliases, beside_fits, d);
  if (options.fit_only.empty() && dynamic)
    hold_traded_lag(set, s, options, current, current_fit, pump_lag_alone, beside_fits, d);
  if (options.fit_only.empty()) read_unnamed_volume_terms(set, s, options, pool, current, current_fit, beside_fits, d);
  hold_other_depth_lag_form(d);
  if (dynamic) widen_lift_at_stall(nominal, obs.track, d);

  const std::vector<double> r_ext = residuals_by_sample(set, current_fit.parameters, current.ctd_density, s.all);
  d.extended_all = rms_where(r_ext, s.all);
  d.extended_heldout_rms_m_s = current_fit.heldout_rms;
  d.gain = 1.0 - current_fit.heldout_rms / d.baseline.heldout_rms_m_s;
  d.speed_through_water = score_speed(set, s.all, s.heldout, current_fit.parameters, current.ctd_density);
  diagnose_pitch_trim_last(steady_model, obs, options, d);
  return d;
}

bool flies_reynolds_prior(const model::VehicleParams& vehicle, const std::optional<double>& asked) {
  const model::Hydrodynamics& h = vehicle.hydro;
  // An exponent set in code (not from a file) counts as stated.
  return !asked && !(h.cd0_reynolds_exponent_stated || h.cd0_reynolds_exponent != 0.0);
}

double drag_reynolds_exponent_for(const model::VehicleParams& vehicle, const std::optional<double>& asked) {
  if (asked) return *asked;
  return flies_reynolds_prior(vehicle, asked) ? kDragReynoldsExponentPrior : vehicle.hydro.cd0_reynolds_exponent;
}

model::VehicleParams diagnosed_nominal(const model::VehicleParams& given, const Diagnosis& d) {
  model::VehicleParams nominal = given;
  nominal.hydro.cd0_reynolds_exponent = d.drag_reynolds_exponent;
  // The exponent flown is stated: an extended vehicle file written from this
  // (and diagnosed again) flies it, 0 included, not the prior.
  nominal.hydro.cd0_reynolds_exponent_stated = true;
  if (d.retrimmed_to_kg_m3) nominal.trim_density_kg_m3 = *d.retrimmed_to_kg_m3;
  return nominal;
}

Predictions predict_all(const model::VehicleParams& given, const Observations& obs, const Diagnosis& d,
                        const DiagnoseOptions& options) {
  const model::VehicleParams nominal = diagnosed_nominal(given, d);
  const FlightModel steady_model(nominal, obs);
  const DynamicFlightModel dynamic_model(nominal, obs.track, options.max_step_s);
  const DepthLagView read(dynamic_model, d.depth_lag_form ? d.depth_lag_form->form : DepthLagForm::kDelay);
  const SampleSet set =
      d.model == FlightModelKind::kDynamic ? dynamic_set(read, obs.track) : steady_set(steady_model, obs);
  Predictions p;
  for (std::size_t i : set.usable) {
    p.time_s.push_back(set.time_s[i]);
    p.depth_m.push_back(set.depth_m[i]);
    p.measured_m_s.push_back(set.measured_m_s[i]);
  }
  if (obs.has_battpos) {
    for (std::size_t i = 0; i < obs.size(); ++i) {
      p.pitch_time_s.push_back(obs.time_s[i]);
      p.pitch_depth_m.push_back(obs.depth_m[i]);
      p.pitch_measured_rad.push_back(obs.pitch_rad[i]);
      p.pitch_nominal_rad.push_back(steady_model.nominal_pitch_rad(i));
      p.pitch_extended_rad.push_back(steady_model.equilibrium_pitch_rad(i, d.extended));
    }
  }
  set.model.predict(nominal_values(), false, set.usable, p.nominal_m_s);
  set.model.predict(d.extended, d.extended_uses_ctd_density, set.usable, p.extended_m_s,
                    d.extended_profile ? &*d.extended_profile : nullptr);
  if (d.speed_through_water) {
    for (std::size_t i : set.usable) p.speed_measured_m_s.push_back(set.model.measured_speed_m_s()[i]);
    set.model.predict_speed(nominal_values(), false, set.usable, p.speed_nominal_m_s);
    set.model.predict_speed(d.extended, d.extended_uses_ctd_density, set.usable, p.speed_extended_m_s);
  }
  return p;
}

}  // namespace glider::diagnose
