// SPDX-License-Identifier: Apache-2.0
#pragma once
// Whether the glides a SIL flight settled on are glides the vehicle can fly.
// A mission's pitch or battery position written for another glider can ask
// for a pitch shallower than the vehicle's best glide allows (paper 002
// eq. 9): no steady flight exists there, and the model settles on a stalled
// branch at a large angle of attack instead (WE01's polar on the comet's
// nsb3.mi climbs at 5 deg pitch, 23 deg angle of attack). The flight is then
// the model's extrapolation, not the vehicle's: the run says so.
#include <string>
#include <vector>

#include "glider/model/hydrodynamics.hpp"
#include "glider/sil/flight_stats.hpp"

namespace glider::sil {

// One warning per settled glide direction (dives, climbs) where most settled
// samples sat at pitches with no steady glide of this polar, naming the share,
// the median pitch and the shallowest glide path the polar allows; empty when
// the glides can be flown.
std::vector<std::string> unflyable_glide_warnings(const model::Hydrodynamics& hydro, double density_kg_m3,
                                                  const FlightStats& stats);

}  // namespace glider::sil
