// SPDX-License-Identifier: Apache-2.0
#pragma once
// How one fitted effect changes over a deployment: its per-segment values
// explained as a constant, a linear trend (fouling: drag grows for weeks) or
// one step (a lost weight, a pump that starts to leak) or a hinge (constant,
// then a line: fouling that starts some day into the deployment), whichever
// the data support. Gliders' per-segment intervals are too narrow (serially
// correlated residuals), so the shapes are judged on the segments' scatter
// about them (least squares with the variance estimated from the residuals),
// never on the per-segment intervals.
#include <cstddef>
#include <span>
#include <string>

#include "glider/fitting_core/intervals.hpp"

namespace glider::diagnose {

enum class TrendShape { kNone, kConstant, kLinear, kStep, kHinge };
const char* to_string(TrendShape shape);

// An estimate and its 95 % interval (the fitting core's, as every plane's).
using Interval = fitting_core::Estimate;

// A bias every segment shares (the Reynolds prior's: one exponent for the
// whole glider) is not in the segments' scatter: a level's interval from the
// scatter alone is too narrow by it. `sigma` is the level's own shift (1
// sigma: the level estimator applied to the segments' shifts - a common-mode
// term, it does not average down with the number of segments), added in
// quadrature to the scatter's 95 % half-width (kZ95 sigma); 0: none. Slopes
// and step changes are differences between segments, where it cancels: not
// widened.
struct SharedBias {
  double sigma = 0.0;
  double between_half_width = 0.0;  // the scatter's own 95 % half-width, before
};

struct Trend {
  TrendShape shape = TrendShape::kNone;  // kNone: fewer than 3 segments with a value
  std::size_t segments = 0;              // with a finite value
  double first_time_s = 0.0;             // of the first segment with a value: day 0
  Interval mean;                         // constant: the mean over the segments
  Interval slope_per_day;                // linear: the rate of change
  Interval at_start;                     // linear: the value at the first segment's time
  // Step: between the last segment before and the first after (times in the
  // input's units), the level before and after, and the change.
  double step_after_s = 0.0, step_before_s = 0.0;
  double level_before = 0.0, level_after = 0.0;
  Interval step_change;
  // Hinge: constant at `hinge_level` up to the segment at `hinge_s`, then a
  // line of `hinge_slope_per_day`; `hinge_end` its value at the last segment.
  double hinge_s = 0.0;
  Interval hinge_level, hinge_slope_per_day, hinge_end;
  // The shared bias in each level's interval (all 0 without shared shifts).
  SharedBias mean_shared, at_start_shared, hinge_level_shared, hinge_end_shared;
  // Two-sided p-values of the linear slope, of the best step and of the best
  // hinge's slope (the step's and the hinge's corrected for the number of
  // places they were searched).
  double p_slope = 1.0, p_step = 1.0, p_hinge = 1.0;
  // Bayesian information criterion of each shape (lower is better).
  double bic_constant = 0.0, bic_linear = 0.0, bic_step = 0.0, bic_hinge = 0.0;

  // The model's value at a time (for plots); NaN for kNone.
  double at(double time_s) const;
  std::string describe(const char* unit) const;
};

using fitting_core::mean_with_interval;

struct TrendOptions {
  double significance = 0.05;     // chance of a spurious line or step in constant data
  std::size_t min_step_side = 2;  // segments on each side of a step; on the line of a hinge (3 at least)
};

// time_s: each segment's time (s, increasing); value: its fitted value (NaN
// where the segment has none, left out). shared_shift (empty: none): each
// segment's shift under a bias all segments share, 1 sigma, signed (the
// Reynolds prior's, Finding::reynolds_prior_shift): widens the levels'
// intervals (SharedBias), never the shape, the slopes or the step's change.
Trend fit_trend(std::span<const double> time_s, std::span<const double> value, const TrendOptions& options = {},
                std::span<const double> shared_shift = {});

}  // namespace glider::diagnose
