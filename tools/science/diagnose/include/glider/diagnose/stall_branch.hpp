// SPDX-License-Identifier: Apache-2.0
#pragma once
// The back side of the polar at a prescribed pitch. With the lift low enough
// for the pitch flown, a glide has a second steady state besides the flight
// branch: a stalled one at a large angle of attack (the polar's blend into
// cross-flow), which the dynamic model (and the SIL) settles on or leaves
// depending on how each inflection ends. Near that lift the depth-rate misfit
// is a saw-tooth: each glide switches branch at the lift where its pitch's
// stall state appears, so no interval from the misfit's local slope holds
// there (lift_change near 0.78 at 26 deg pitch on the comet vehicle).
// Whether a polar has that state at a pitch: model::has_stall_glide.
#include <span>

#include "glider/diagnose/flight_model.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

// The lift factor (lift_change) below which a glide at |pitch_rad| has that
// stalled steady state, the other effects as in `values`; 0 if it has none
// in lift_change's plausible range, and that range's top if it has one at
// every plausible lift.
double stall_onset_lift(const model::VehicleParams& nominal, const EffectValues& values, double pitch_rad);

// [low, high] of the stall onsets over the glides' pitches (the 1st to 99th
// percentile of |pitch| of the samples, descending and climbing apart; a
// pitch that never stalls adds nothing); {0, 0} if none stalls.
struct LiftBand {
  double low = 0.0, high = 0.0;
};
LiftBand stall_onset_band(const model::VehicleParams& nominal, const EffectValues& values,
                          std::span<const double> pitch_rad);

}  // namespace glider::diagnose
