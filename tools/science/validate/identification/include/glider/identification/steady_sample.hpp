// SPDX-License-Identifier: Apache-2.0
#pragma once
// Inputs of the steady-glide identification of paper 000 (Graver et al.
// 2003, sec. 3): one steady glide averaged over its interval (as in the
// paper's Table 1), and the lift model the glides are read through.
#include "glider/model/vehicle.hpp"

namespace glider::identification {

struct SteadyGlideSample {
  double pitch_rad = 0.0;       // + nose up
  double depth_rate_m_s = 0.0;  // + descending
  // Net buoyancy from the pump alone, + heavy (= -rho * pumped volume): paper
  // 000's ballast mass m_b. The unknown buoyancy trim offset is added to it.
  double ballast_net_kg = 0.0;
  double battery_pos_m = 0.0;  // pitch battery slide as logged, + forward (m_battpos / 39.37)
  double second_pos_m = 0.0;   // second moving mass, if the vehicle has one
};

// One standard deviation of every sample's inputs, propagated into the
// estimates where asked; 0 = that input is taken as exact.
struct SampleUncertainty {
  double pitch_rad = 0.0;
  double depth_rate_m_s = 0.0;
  double ballast_kg = 0.0;
  double battery_pos_m = 0.0;  // used by the pitch-moment estimates only
};

// C_L(a) and rho A: all the lift equation needs. The lift curve is
// model::force_coefficients(hydro, a).lift (the fit inside
// hydro.fit_valid_to_rad); A = hydro.reference_area_m2. The drag and moment
// members of `hydro` are not used: they are what is being identified.
struct LiftModel {
  model::Hydrodynamics hydro;
  double density_kg_m3 = 1025.0;
  double gravity_m_s2 = 9.81;
};

// The vehicle's lift curve and area in water of its trim density.
LiftModel lift_model_of(const model::VehicleParams& vehicle);

}  // namespace glider::identification
