// SPDX-License-Identifier: Apache-2.0
#pragma once
// Paper 000 sec. 3.2, eq. (14): the drag polar C_D = cd0 + cd_alpha2 a^2
// (even in a: the vehicle is symmetric top to bottom) fitted by linear least
// squares to the drag coefficients of the steady glides.
#include <span>

#include "glider/identification/lift_glide.hpp"

namespace glider::identification {

struct DragPolarFit {
  bool ok = false;  // at least two glides at different |a|
  double cd0 = 0.0;
  double cd_alpha2_per_rad2 = 0.0;
  // The fit's own standard errors (NaN with exactly two glides). They take
  // the angles of attack as exact, but a glide's a and C_D come from the same
  // measured depth rate and pitch: on noisy glides they are ~1.5 times too
  // small (Monte Carlo on synthetic glides), hence the propagated ones below.
  double cd0_se = 0.0;
  double cd_alpha2_se_per_rad2 = 0.0;
  // Input uncertainty and buoyancy-offset uncertainty carried through the
  // reading of every glide and the fit (estimate_drag_polar; 0 if none given).
  // Their size is right, but noisy depth rates also bias the fit: a glide's
  // a and C_D both scale as 1/zdot^2, so its error runs along a line steeper
  // than the polar and pulls cd_alpha2 up and cd0 down (errors in
  // variables). Monte Carlo, 37 WE01 glides with 3 mm/s of depth-rate noise:
  // cd0 -0.5 %, cd_alpha2 +2 %, half a standard error; it grows as the noise
  // squared.
  double cd0_input_se = 0.0;
  double cd_alpha2_input_se_per_rad2 = 0.0;
  double residual_sd = 0.0;  // of the C_D values about the fit
  int glides = 0;
};

DragPolarFit fit_drag_polar(std::span<const GlideFromLift> glides);

struct DragPolarOptions {
  SampleUncertainty input_sd;
  double buoyancy_offset_sd_kg = 0.0;
};

// Reads the samples with the buoyancy offset, fits the polar and propagates
// the options' uncertainties (central differences, inputs independent).
// Not ok if a glide cannot be read.
DragPolarFit estimate_drag_polar(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                 double buoyancy_offset_kg, const DragPolarOptions& options = {});

}  // namespace glider::identification
