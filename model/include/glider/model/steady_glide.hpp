#pragma once
// Steady (equilibrium) glides of the vertical-plane model, paper 000 eqs.
// (4)-(6): in a steady straight glide lift and drag balance the net weight,
//   D = m0 g sin(gamma), L = m0 g cos(gamma),  gamma = glide path below horizontal,
// so tan(gamma) = C_D(a) / C_L(a) fixes the angle of attack and
//   V^2 = 2 m0 g / (rho A sqrt(C_L^2 + C_D^2)) the speed.
#include <optional>
#include <string>

#include "glider/model/vehicle.hpp"

namespace glider::model {

struct SteadyGlide {
  double glide_path_rad = 0.0;  // xi = theta - alpha (negative descending)
  double alpha_rad = 0.0;
  double pitch_rad = 0.0;
  double speed_m_s = 0.0;
  double depth_rate_m_s = 0.0;        // + descending
  double horizontal_speed_m_s = 0.0;
};

struct SteadyGlideResult {
  std::optional<SteadyGlide> glide;
  std::string error;  // why there is no glide (e.g. steeper than possible)
};

// Steady glide with the given glide path angle magnitude (deg, > 0) and net
// buoyancy (kg: + heavy = descending, - light = climbing). Of the two angles
// of attack that give the same path, the one with less drag (the flight
// branch of paper 000 Fig. 12).
SteadyGlideResult steady_glide_for_path(const Hydrodynamics& hydro, double density_kg_m3,
                                        double glide_path_deg, double net_buoyancy_kg, double gravity_m_s2 = 9.81);

// Shallowest possible glide path (deg): at the angle of attack of maximum
// lift-to-drag ratio.
double min_glide_path_deg(const Hydrodynamics& hydro);

}  // namespace glider::model
