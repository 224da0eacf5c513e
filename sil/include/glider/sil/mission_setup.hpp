// SPDX-License-Identifier: Apache-2.0
#pragma once
// What a mission needs from the vehicle model before launch: the limits a
// Slocum mission is checked against, and the flight model's angle-of-attack
// table for dead reckoning (the firmware cannot call the model: it gets a
// table at init time).
#include "glider/firmware/dead_reckoning.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::sil {

// The pump, slide and fin travel of the model as firmware limits.
fw::mission_file::MissionVehicle mission_vehicle(const model::VehicleParams& vehicle, double max_working_depth_m);

// kFlightModel dead reckoning: |alpha| of the model's steady glide at each
// |pitch| of the table, for dives and climbs, in water of `density_kg_m3`.
// Pitches shallower than the best glide have no steady glide: they take the
// nearest steeper entry. The coast time constant through inflections is the
// surge momentum over the drag's damping at a 25 deg glide.
fw::DeadReckoningConfig flight_model_dead_reckoning(const model::VehicleParams& vehicle, double density_kg_m3,
                                                    fw::DeadReckoningConfig base = {});

}  // namespace glider::sil
