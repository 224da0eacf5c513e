// SPDX-License-Identifier: Apache-2.0
#pragma once
// The SIL's source of the flight application's vehicle setup
// (glider/firmware/app/vehicle_setup.hpp): derived from the vehicle model, the
// data the target reads from its board file. The limits a Slocum mission is
// checked against, and the flight model's angle-of-attack table for dead
// reckoning (the firmware cannot call the model: it gets a table at init time).
#include <filesystem>

#include "glider/firmware/app/vehicle_setup.hpp"
#include "glider/firmware/dead_reckoning.hpp"
#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::sil {

// The pump, slide and fin travel of the model as firmware limits.
fw::mission_file::MissionVehicle mission_vehicle(const model::VehicleParams& vehicle, double max_working_depth_m);

// The whole setup: limits, fin, `fitted` devices, and (with
// `flight_model_dr`) the alpha table in water of `density_kg_m3`.
fw::app::VehicleSetup vehicle_setup(const model::VehicleParams& vehicle, const fw::app::FittedDevices& fitted,
                                    double max_working_depth_m, bool flight_model_dr, double density_kg_m3);

// The [fitted] table of a vehicle file (the model's reader leaves it to the
// firmware). Defaults: leak detector, rudder and power monitor fitted, no drop weight.
fw::app::FittedDevices load_fitted_devices(const std::filesystem::path& vehicle_file);

// kFlightModel dead reckoning: |alpha| of the model's steady glide at each
// |pitch| of the table, for dives and climbs, in water of `density_kg_m3`.
// Pitches shallower than the best glide have no steady glide: they take the
// nearest steeper entry. The coast time constant through inflections is the
// surge momentum over the drag's damping at a 25 deg glide.
fw::DeadReckoningConfig flight_model_dead_reckoning(const model::VehicleParams& v, double density_kg_m3,
                                                    fw::DeadReckoningConfig dr = {});

}  // namespace glider::sil
