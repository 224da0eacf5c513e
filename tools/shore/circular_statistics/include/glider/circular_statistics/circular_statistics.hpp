// SPDX-License-Identifier: Apache-2.0
#pragma once
// The statistics of angles (headings) that do not break at north: 359° and 1°
// are 2° apart, not 358°. Each angle is a unit vector; their (weighted) mean
// vector's length R is 1 for one angle repeated and falls towards 0 as they
// spread. Health's heading spread (a segment's circular sd) and the forecast's
// course straightness (a dive's time-weighted R) both read it from here.

namespace glider::circular_statistics {

// The running sums of a set of angles' unit vectors, each times its weight.
class MeanResultant {
 public:
  // One angle in radians; a weight of 0 adds nothing.
  void add(double angle_rad, double weight = 1.0);
  // The sum of the weights added (the count when every weight is 1).
  double total_weight() const { return total_weight_; }
  // R = |sum w (cos, sin)| / sum w, in [0, 1]; NaN when the weights sum to 0.
  double length() const;

 private:
  double sin_sum_ = 0.0;
  double cos_sum_ = 0.0;
  double total_weight_ = 0.0;
};

// The circular standard deviation sqrt(-2 ln R) in radians (the ordinary sd
// for a small spread; grows without bound as R falls to 0, which is held at
// 1e-300 so the result is finite). NaN for a NaN R.
double circular_sd_rad(double mean_resultant_length);

}  // namespace glider::circular_statistics
