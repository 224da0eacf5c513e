// SPDX-License-Identifier: Apache-2.0
#pragma once
// Delay-type parameters (pump lag, depth lag, fin, yaw and autopilot
// delays; issue 26 item 4): a residual that shifts a signal in time has a
// minimum every time the shifted signal lines up with a feature of the
// log, so a local fit started at a fixed guess stops in the nearest one
// (a 40 s pump lag read as ~20 s). The fit starts instead from the best
// point of a grid over the allowed range, and an interval the Jacobian
// cannot give (a flat or exact residual: zero width) comes from the profile
// of the residual over that grid, never narrower than its resolution.
#include <functional>

#include <vector>
#include "glider/fitting_core/intervals.hpp"

namespace glider::fitting_core {

// Delays from `low` to `high` (both included) every `step`; the grid's
// resolution is its step.
struct DelayGrid {
  std::vector<double> values;
  double resolution_s = 0.0;
};
DelayGrid delay_grid(double low, double high, double step);

// 0, step/2, step, 2 step, 4 step, ... and `high`: a few points over a range
// where each flight is costly (the pump lag: 0, 2.5, 5, 10, ... 80, 120 s,
// 8 flights), the local fit's basin growing with the delay. Its resolution:
// the widest step.
DelayGrid doubling_delay_grid(double step, double high);

// The grid's step at `value` (of the cell holding it).
double resolution_at(const DelayGrid& grid, double value);

// The grid value with the least RSS, `rss` per grid value; of a run of equal
// least values, its middle.
double best_on_grid(const DelayGrid& grid, const std::vector<double>& rss);

// The RSS of `objective` at every grid value.
std::vector<double> rss_on_grid(const DelayGrid& grid, const std::function<double(double)>& objective);

// The training RSS a one-parameter 95 % profile may reach: `best_rss` plus
// 3.84 noise variances, the noise from `n_eff` independent samples and `k`
// parameters (every grid profile: delays, thresholds).
double profile_threshold(double best_rss, double n_eff, int k);

// The 95 % profile interval: the grid values whose RSS is within 3.84 noise
// variances of the best fit's (`fitted_rss` at `value`, or the grid's best if
// lower), the noise variance from `n_eff` independent samples and `k`
// parameters; widened by a step each side (the bound lies somewhere before
// the first grid value outside), within the grid's range, and holding
// `value`.
Interval profile_interval(const DelayGrid& grid, const std::vector<double>& rss, double value, double fitted_rss,
                          double n_eff, int k);

// `interval` widened to at least `resolution` around `value`, not below `floor`.
Interval at_least_resolution(Interval interval, double value, double resolution, double floor);

// A Jacobian's half-width that says nothing: zero (a flat or exact residual)
// or not finite.
bool jacobian_failed(double half_width, double scale);

}  // namespace glider::fitting_core
