// SPDX-License-Identifier: Apache-2.0
#pragma once
// The root of the up/down symmetry criterion alone (no uncertainties, no
// pairs), for re-estimating the offset under perturbed inputs. Private.
#include <optional>
#include <span>

#include "glider/identification/buoyancy_offset.hpp"

namespace glider::identification::detail {

// near_kg: a root expected close by (a perturbed problem) is searched for
// there first, which is much cheaper than scanning every feasible offset.
std::optional<double> solve_offset(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                   const BuoyancyOffsetOptions& options, std::optional<double> near_kg = {});

}  // namespace glider::identification::detail
