// SPDX-License-Identifier: Apache-2.0
#pragma once
// The yaw a vertical shear of the current makes (docs/diagnose/heading.md,
// "Current shear"): a glider crossing water whose current changes with
// depth turns by -depth rate x d(starboard current)/d(depth) / V
// (model/dynamics.hpp), the opposite way on dives and climbs at the same
// depth. Fitted, depth bin by depth bin, on the yaw rate the vehicle link
// leaves; a profile, not an effect of the vocabulary.
#include <cstddef>
#include <span>
#include <vector>

#include "glider/diagnose/heading_track.hpp"

namespace glider::diagnose {

struct ShearBin {
  double from_m = 0.0, to_m = 0.0;
  double shear_per_s = 0.0;  // d(starboard current)/d(depth), 1/s (0 where not fitted)
  double ci95_low = 0.0, ci95_high = 0.0;
  std::size_t runs = 0;  // glides with samples in the bin (the interval's clusters)
  bool fitted = false;   // at least two glides of the fitted yos cross it
};

struct ShearProfile {
  std::vector<ShearBin> bins;
  // Held-out yaw rate RMS (rad/s) of the vehicle link's model without and
  // with the profile, on the alternate yos it was not fitted on.
  double heldout_rms_before = 0.0, heldout_rms_after = 0.0;
  // Per bin, dives and climbs fitted apart: the correlation of the two
  // profiles (a shear gives the same one from both; 0 when undefined).
  double dive_climb_correlation = 0.0;
};

// The regressor of a sample: the yaw rate a shear of 1/s makes there.
double shear_yaw_per_unit(const HeadingTrack& t, std::size_t sample);

// `residual`: measured - modelled yaw rate per track sample (NaN where
// none); `samples`: the ones to use (sorted). Bins of `bin_m` from 0 m;
// fitted on even yos, scored on odd ones; intervals Student-t over glides.
ShearProfile fit_current_shear(const HeadingTrack& t, std::span<const double> residual,
                               std::span<const std::size_t> samples, double bin_m = 5.0);

// The starboard current's shear at a depth (0 outside the fitted bins).
double shear_at(const ShearProfile& p, double depth_m);

}  // namespace glider::diagnose
