// SPDX-License-Identifier: Apache-2.0
#pragma once
// The truth simulator's vehicle: a rigid body with a centre of gravity that
// moves with the battery, added masses, and the hydrodynamics below. Its
// numbers are read from a vehicle file of boards/ (the published values
// cited there: slocum_shallow.toml for the shallow-like variant, Merckelbach
// et al. 2019 and glidertrim; slocum_we01.toml for the deeper WE01-like one,
// Graver et al. 2003; /work/shared/data/papers/README.md), interpreted here
// with this simulator's own equations. What the project's model lacks, and
// is drawn per log (model-form error, never fitted by the diagnosis):
// - a lag of the lift behind the angle of attack (circulation build-up,
//   Wagner-like, time constant lift_lag_chords x chord / speed);
// - lift from the pitch rate (the wings aft of the centre: cl_q);
// - skin-friction drag that falls with speed (C_D0 ~ (V / V_ref)^-n, the
//   Reynolds number's effect; equal to the file's C_D0 at V_ref);
// - a second yaw pole (sway) and a roll the fin induces, lagged;
// - the battery as a quasi-static shift of the centre of gravity (no
//   internal-mass reaction forces).
#include <string>

namespace glider::truth {

struct Hydro {
  double area_m2 = 0.1;
  double cl0 = 0.0, cl_alpha = 0.0, cl_alpha_abs_alpha = 0.0;  // lift slope of hull and wings together
  double cd0 = 0.0, cd_alpha2 = 0.0;                           // induced drag of hull and wings together
  double cm0_m = 0.0, cm_alpha_m = 0.0, cmq_m2 = 0.0;          // viscous moment (the Munk moment is separate)
  double cn90 = 1.0, fit_valid_to_rad = 0.17, crossflow_from_rad = 0.44;
  double wing_lift_share = 0.0;  // fraction of cl_alpha from the wings (scaled by lift_change with their drag)
  double wing_induced_cd_alpha2 = 0.0;
};

struct HeadingParams {
  double fin_yaw_gain_per_m = 0.15, roll_yaw_gain_per_m = -2.1, yaw_time_constant_s = 2.0;
  double roll_rad = 0.0, fin_max_rad = 0.47, fin_rate_rad_s = 0.1, fin_delay_s = 0.0, fin_deadband_rad = 0.0;
};

// The model-form terms above, with the values a log draws.
struct Unmodelled {
  double lift_lag_chords = 2.0, chord_m = 0.12;
  double cl_q = 1.0;  // lift per pitch rate x chord / speed
  double drag_reynolds_exponent = 0.1, drag_reference_speed_m_s = 0.35;
  double yaw_second_pole_s = 0.5;
  double fin_roll_per_rad = 0.1, roll_time_constant_s = 3.0;
};

struct Vehicle {
  std::string name;
  double hull_kg = 0.0, hull_inertia_kg_m2 = 0.0;
  double offset_kg = 0.0, offset_x_m = 0.0, offset_z_m = 0.0;
  double battery_kg = 0.0, battery_x_at_zero_m = 0.0, battery_z_m = 0.0;
  double battery_min_m = 0.0, battery_max_m = 0.0, battery_rate_m_s = 0.0;
  double ballast_x_m = 0.0, ballast_min_m3 = 0.0, ballast_max_m3 = 0.0, pump_rate_m3_s = 0.0;
  double pump_lag_s = 0.0;  // displaced volume behind the pump's reading (hidden effect pump_lag)
  double added_x_kg = 0.0, added_z_kg = 0.0, added_inertia_kg_m2 = 0.0;
  double trim_density_kg_m3 = 1025.0, buoyancy_offset_kg = 0.0;  // mass - trim density x volume
  double hull_compressibility_per_pa = 0.0, thermal_expansion_per_k = 0.0, reference_temperature_c = 10.0;
  Hydro hydro;
  HeadingParams heading;
  Unmodelled unmodelled;

  double mass_kg() const { return hull_kg + offset_kg + battery_kg; }
  // Hull volume at the surface and the reference temperature, pump at 0.
  double volume_m3() const { return (mass_kg() - buoyancy_offset_kg) / trim_density_kg_m3; }
};

// Reads the published numbers of a boards/ vehicle file (keys of
// boards/README.md). Throws std::runtime_error naming the file and key.
Vehicle load_vehicle(const std::string& path);

}  // namespace glider::truth
