// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the depth-averaged current over the coming dive can be, before the
// history says much: a Gaussian prior over the water - a steady mean plus an
// M2 tide of unknown amplitude and phase - conditioned on the glider's
// per-segment estimates (Gaussian-process regression; each estimate and the
// prediction are means over their segments). With one or two estimates no
// hindcast can choose a rule or measure its error; this gives both the
// prediction and its uncertainty from a stated prior (docs/forecast.md,
// "The current"):
//   mean current   N(0, 0.10 m/s) per component,
//   M2 tide        cos and sin coefficients N(0, 0.25 m/s) per component
//                  (mean amplitude 0.31 m/s: a shelf sea's tide),
//   each estimate  off its segment's true mean by N(0, 0.02 m/s) (the DR's
//                  speed error and the fix's noise over a segment).
// Over half an hour the tide moves little and the prediction is persistence;
// a quarter period (3.1 h) on, the last estimate says almost nothing about
// the water and the prediction falls back towards the mean, its sigma
// growing to the prior's.
#include <vector>

#include "glider/forecast/current_estimate.hpp"

namespace glider::forecast {

// The principal lunar semidiurnal tide's period (12.42 h).
inline constexpr double kM2PeriodS = 44714.16;

struct TidalPrior {
  double mean_sigma_m_s = 0.10;
  double m2_sigma_m_s = 0.25;
  double estimate_sigma_m_s = 0.02;
};

// The posterior mean current over [from_utc_s, to_utc_s] and its 1-sigma,
// from the estimates of the last day before from_utc_s (method "tidal
// prior"); with none, the prior itself.
CurrentEstimate predict_with_prior(const std::vector<CurrentSample>& samples, double from_utc_s, double to_utc_s,
                                   const TidalPrior& prior = {});

// The prior's variance (per component) of persistence's error: the mean over
// [from_utc_s, to_utc_s] less the estimate `last` (what carrying `last`
// forward costs in this water before any hindcast has measured it).
double persistence_prior_variance(const CurrentSample& last, double from_utc_s, double to_utc_s,
                                  const TidalPrior& prior = {});

}  // namespace glider::forecast
