// SPDX-License-Identifier: Apache-2.0
#pragma once
// Intervals that are never narrower than the data support (issue 26 item 4).
// A Jacobian's interval is only as good as its finite difference: a residual
// that moves in steps (a flight whose samples, branches or clamps change
// with the parameter) gives a column far too steep or exactly flat over the
// tiny difference step, and the covariance then says a parameter is known to
// a few parts per million (seen: thermal expansion 0.000212923
// [0.0002129226, 0.0002129235] on a truth log). The check asks the residual
// itself: at the interval's ends the training RSS must have risen by about
// the 95 % profile threshold (3.84 noise variances; in a linear fit the
// marginal interval's ends raise the conditional RSS by at least that). Where
// it has risen by far less, the interval is widened to the conditional
// profile's, stepping out by doublings until the RSS crosses the threshold.
#include <functional>

namespace glider::fitting_core {

// Fraction of the profile threshold's rise the Jacobian interval's ends must
// reach to be kept. A linear fit reaches >= 1; a quarter leaves room for an
// honestly curved residual (the interval then is within a factor ~2 of its
// profile) and catches a Jacobian off by orders of magnitude.
inline constexpr double kProfileRiseKept = 0.25;

// The most doublings from the first step: 2^40 covers a Jacobian off by
// 1e12; each is one flight, spent only where the Jacobian failed.
inline constexpr int kProfileMaxDoublings = 40;

// The 95 % half-width of a parameter at `value` the data support: `half`
// (the Jacobian's) where `rss_at` (the training RSS with the parameter at x,
// the others held at the fit) rises at value +- half by at least
// kProfileRiseKept of the threshold's rise over `fitted_rss`
// (profile_threshold(fitted_rss, n_eff, k)); else, on that side, the first
// doubling of the step (from max(half, `min_step`)) whose RSS crosses the
// threshold - the farthest tried where none does. Never less than `half`.
double profile_checked_half_width(double value, double half, double fitted_rss, double n_eff, int k, double min_step,
                                  const std::function<double(double)>& rss_at);

}  // namespace glider::fitting_core
