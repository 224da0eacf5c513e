// SPDX-License-Identifier: Apache-2.0
#pragma once
// How many independent samples a fit's residuals hold. A glider log's
// samples are 1-8 s apart on minute-long glides: neighbours share one model
// error, so n samples carry far less than n independent ones, and every
// interval, information criterion and profile threshold that counts them
// as n is too sure of itself. One rule for every plane (issue 26 item 5).
#include <span>

namespace glider::fitting_core {

// n (1 - r1) / (1 + r1): the independent samples of an AR(1) with the lag-1
// autocorrelation r1 of the deviations from `mean` (r1 clamped to 0..0.99).
double effective_sample_count(std::span<const double> x, double mean = 0.0);

}  // namespace glider::fitting_core
