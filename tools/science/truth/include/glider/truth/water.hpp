// SPDX-License-Identifier: Apache-2.0
#pragma once
// The truth's ocean: a thermocline (tanh) in temperature and a halocline in
// salinity, heaved by a mode-1 internal wave whose vertical velocity is
// w = W sin(pi z / H) cos(omega t + phase) (zero at the surface and at the
// bottom H, largest mid-column: the first baroclinic mode of a
// constant-stratification column); a horizontal current with linear shear;
// an optional steady depth-structured vertical velocity (the hidden effect
// vertical_water_velocity). Density from its own linear equation of state
// with in-situ compression (not TEOS-10, which the diagnosis uses):
// rho = rho0 (1 - a (T - 10) - b (T - 10)^2 + c (S - 35)) + k z.
#include <cstdint>
#include <random>

namespace glider::truth {

struct Water {
  double surface_temperature_c = 18.0, deep_temperature_c = 8.0;
  double thermocline_m = 40.0, thermocline_thickness_m = 12.0;
  double surface_salinity = 34.8, deep_salinity = 35.2;
  double bottom_m = 200.0;  // H of the internal-wave mode
  double wave_w_m_s = 0.004, wave_period_s = 1800.0, wave_phase_rad = 0.0;
  double current_east_m_s = 0.1, current_north_m_s = 0.05, shear_per_s = 0.001;  // current at z: (1 - shear z / |c|)
  // Hidden vertical velocity (+ down, as depth): w0 s(z) with s a layer
  // between its depths (smooth edges) or, with layer_to_m <= 0, a mode-1 shape.
  double hidden_w_m_s = 0.0, hidden_w_from_m = 0.0, hidden_w_to_m = 0.0;
  double compression_kg_m3_per_m = 4.5e-3;
  double density_offset_kg_m3 = 0.0;  // sets the column's density where the vehicle was trimmed for it  // in-situ
                                      // density rise with depth (seawater's compressibility)

  double heave_m(double z, double t_s) const;  // isopycnal displacement (+ down)
  double temperature_c(double z, double t_s) const;
  double salinity(double z, double t_s) const;
  double density_kg_m3(double z, double t_s) const;          // in situ
  double vertical_velocity_m_s(double z, double t_s) const;  // + down: waves and the hidden part
  double hidden_vertical_velocity_m_s(double z) const;
  void current_m_s(double z, double& east, double& north) const;
};

// A water column drawn for a log: thermocline depth and strength, wave
// amplitude (2-6 mm/s), period (15-60 min) and phase, current and shear.
Water draw_water(std::mt19937_64& rng, double dive_to_m);

}  // namespace glider::truth
