// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the depth-averaged current over the coming dive can be, before the
// history says much: a Gaussian prior over the water - a steady mean plus an
// M2 tide of unknown amplitude and phase - conditioned on the glider's
// per-segment estimates (Gaussian-process regression; each estimate and the
// prediction are means over their segments). With one or two estimates no
// hindcast can choose a rule or measure its error; this gives both the
// prediction and its uncertainty (docs/forecast.md, "The current").
//
// The prior's widths are the pilot's (a `glider-forecast` option, or the
// glider folder's forecast.toml), by default a shelf sea's:
//   mean current   N(0, 0.10 m/s) per component,
//   M2 tide        cos and sin coefficients N(0, 0.25 m/s) per component
//                  (mean amplitude 0.31 m/s),
//   each estimate  off its segment's true mean by N(0, 0.02 m/s) (the DR's
//                  speed error and the fix's noise over a segment),
//                  and by a position error of N(0, 100 m) over the
//                  segment's time (the fix it dived from, the DR's restart
//                  as it dived, the drift before it: a distance, so a short
//                  segment's estimate is the noisier one).
// Mode "evidence" (the default) lets the estimates choose the widths: the
// mean's and the tide's each scaled by 2, 1, 1/2 ... 1/32 (every pair a
// hypothesis, equally likely beforehand: steady water, a pure tide, both, weak
// or strong), each weighted by its marginal likelihood of the estimates so
// far (Bayesian model averaging; the prediction is the mixture's mean and
// variance); the position error scaled by 2, 1, 1/2, 1/4, 1/8 (each 0.1
// likely beforehand) or 0 (0.5: a precise glider), so two estimates that
// differ are weighed as a tide's change against a noisy short segment, and
// the prediction spread over both. Weak water then stops paying for a shelf
// sea's tide after one estimate, and a strong tide is not held back by the
// pilot's guess. Mode "fixed" uses the widths as given; "off" uses no prior
// (persistence).
//
// With the pilot's tide table (tide_table.hpp) the tide is no longer of
// random phase: the prior's mean is the table's current (averaged over each
// segment), and the tide's width is what the table may be wrong by (its
// amplitudes' and phases' sigmas, linearised; in evidence mode scaled by the
// same 2 .. 1/32 as the M2 width, each component conditioned on its own).
#include <memory>
#include <string>
#include <vector>

#include "glider/forecast/current_estimate.hpp"
#include "glider/forecast/tide_table.hpp"

namespace glider::forecast {

// The principal lunar semidiurnal tide's period (12.42 h).
inline constexpr double kM2PeriodS = 44714.16;

enum class PriorMode { kEvidence, kFixed, kOff };

struct TidalPrior {
  double mean_sigma_m_s = 0.10;
  double m2_sigma_m_s = 0.25;
  double estimate_sigma_m_s = 0.02;
  double position_sigma_m = 100.0;  // per component, over the estimate's segment (span_s)
  PriorMode mode = PriorMode::kEvidence;
  std::shared_ptr<const TideTable> tide;  // the pilot's constituents (null: an M2 of random phase)
  double tide_error_scale = 1.0;          // the table's errors scaled by (evidence mode's hypotheses)
};

// "evidence" | "fixed" | "off"; parse_prior_mode throws std::invalid_argument for another text.
const char* to_string(PriorMode mode);
PriorMode parse_prior_mode(const std::string& text);

// Allowed ranges (m/s): the widths 0-2 (0: that part absent), the estimate's
// noise 0.001-1 (it keeps the regression well posed), the position error
// 0-5000 m. Throws
// std::invalid_argument naming the field, the value and the range (NaN too).
void check_prior(const TidalPrior& prior);

// The posterior mean current over [from_utc_s, to_utc_s] and its 1-sigma,
// from the estimates of the last day before from_utc_s (method "tidal
// prior"); with none, the prior itself (the mixture's, in evidence mode).
CurrentEstimate predict_with_prior(const std::vector<CurrentSample>& samples, double from_utc_s, double to_utc_s,
                                   const TidalPrior& prior = {});

// The prior's variance (per component) of persistence's error: the mean over
// [from_utc_s, to_utc_s] less the estimate `last` (what carrying `last`
// forward costs in this water before any hindcast has measured it). In
// evidence mode the hypotheses are weighted by `samples` (the last day's).
double persistence_prior_variance(const CurrentSample& last, double from_utc_s, double to_utc_s,
                                  const TidalPrior& prior = {}, const std::vector<CurrentSample>& samples = {});

// The widths the estimates favour (evidence mode: the posterior mean of each
// width over the hypotheses; else the prior's own), for the notes.
TidalPrior favoured_prior(const std::vector<CurrentSample>& samples, double from_utc_s, const TidalPrior& prior = {});

}  // namespace glider::forecast
