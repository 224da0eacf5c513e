// SPDX-License-Identifier: Apache-2.0
#pragma once
// The held-out error a selection compares: the RMS of the residuals averaged
// over blocks of a glide, not of the samples one by one. A logged depth rate
// is the slope of a noisy depth (0.07 m, Slocum's) over +-5 s: about 9 mm/s
// of noise, fresh every few samples, that no model of the flight can
// predict. In the sample RMS an effect of a few mm/s that lasts a whole glide
// (a hull that compresses over 100 m, expands over 8 K) lowers it by
// s^2 / 2 sigma^2, a percent or two, under any margin worth having, while
// its interval lies several sigma from zero; averaged over a block the noise
// falls as the block's independent samples and the effect stays. A block is
// the held-out samples of one glide (its cluster) within `block_s` seconds
// of the block's first.
#include <span>

namespace glider::fitting_core {

// sqrt(sum_b n_b mean_b^2 / sum_b n_b) over the blocks b of `residual`
// (time-ordered within each cluster; a new block at a new cluster or
// `block_s` after the block's first sample). `block_s` <= 0: the plain RMS.
// NaN for no residuals.
double block_rms(std::span<const double> time_s, std::span<const long> cluster, std::span<const double> residual,
                 double block_s);

}  // namespace glider::fitting_core
