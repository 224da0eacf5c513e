// SPDX-License-Identifier: Apache-2.0
#pragma once
// Tidal constituents fitted to a deployment's depth-averaged currents (least
// squares: a mean and each constituent's cos and sin per component, each
// estimate the mean over its segment), with their intervals: what a pilot
// writes as the tide table (tide_table.hpp) for a later deployment at the
// same place (`glider forecast fit-tide`; docs/forecast.md, session 44).
#include <string>
#include <vector>

#include "glider/forecast/current_estimate.hpp"
#include "glider/forecast/tide_table.hpp"

namespace glider::forecast {

struct TideFit {
  TideTable table;  // the amplitudes, phases and their 1-sigma (sigmas the larger of east's and north's)
  int estimates = 0;
  double record_s = 0.0;                                     // first segment's start to the last one's end
  double residual_east_m_s = 0.0, residual_north_m_s = 0.0;  // RMS residual of each component
  double t95 = 1.96;  // Student's t (the residual's degrees of freedom): a 95 % interval is +- t95 sigma
};

// The record needed to fit `names` apart (the Rayleigh criterion: each
// constituent's period, to tell it from the mean, and 1 / |f1 - f2| for
// every pair), in seconds.
double tide_fit_record_needed_s(const std::vector<std::string>& names);

// Fits `names` to `samples` with the phases referred to `reference_utc_s`.
// Throws std::runtime_error for an unknown name, a record shorter than the
// criterion (naming the pair or constituent and the spans), or fewer
// estimates than the fit's parameters + 2 (an interval needs a residual).
TideFit fit_tide(const std::vector<CurrentSample>& samples, const std::vector<std::string>& names,
                 double reference_utc_s);

}  // namespace glider::forecast
