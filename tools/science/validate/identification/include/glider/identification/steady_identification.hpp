// SPDX-License-Identifier: Apache-2.0
#pragma once
// Paper 000 sec. 3 in one call, in the paper's order: the buoyancy trim
// offset (3.2), the drag polar with it (eq. 14), then the pitch moment and
// static pitch trim (3.3). The building blocks are in the other headers.
#include <span>

#include "glider/identification/buoyancy_offset.hpp"
#include "glider/identification/drag_fit.hpp"
#include "glider/identification/pitch_trim.hpp"

namespace glider::identification {

struct SteadyIdentification {
  BuoyancyOffsetEstimate buoyancy;
  DragPolarFit drag;
  PitchTrimEstimate pitch;
  bool ok() const { return buoyancy.ok && drag.ok && pitch.ok; }
};

// The drag's and pitch's *_input_se are those of the whole chain: for every
// perturbed input the offset is estimated again (the offset and the glides'
// drag and moments share the same measurements). Scatter of the offset beyond
// what the inputs explain (residual_se_kg above input_se_kg) is carried
// through as one more independent error.
SteadyIdentification identify_steady_glides(const model::VehicleParams& vehicle, const LiftModel& lift,
                                            std::span<const SteadyGlideSample> samples,
                                            const BuoyancyOffsetOptions& options = {});

}  // namespace glider::identification
