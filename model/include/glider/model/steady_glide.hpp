// SPDX-License-Identifier: Apache-2.0
#pragma once
// Steady (equilibrium) glides of the vertical-plane model, paper 000 eqs.
// (1)-(6): in a steady straight glide lift and drag balance the net weight,
//   D = m0 g sin(gamma), L = m0 g cos(gamma),  gamma = glide path below/above horizontal,
// so tan(gamma) = C_D(a) / |C_L(a)| fixes the angle of attack and
//   V^2 = 2 |m0| g / (rho A sqrt(C_L^2 + C_D^2)) the speed; the pitching
// moment (internal masses, viscous moment, Munk) must vanish too, which
// fixes where the battery has to be. Glides shallower than the best glide
// ratio do not exist (paper 002 eq. 9, here for any C_L, C_D).
// With a skin friction that follows the Reynolds number
// (Hydrodynamics::cd0_reynolds_exponent > 0) C_D depends on V, and every
// solver here is the fixed point of the speed-independent one at
// cd0 (V / V_ref)^-n; min_glide_path_deg and has_stall_glide take the
// file's cd0 (the drag at its reference speed).
#include <optional>
#include <string>

#include "glider/model/dynamics.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::model {

struct SteadyGlide {
  double glide_path_rad = 0.0;  // xi = theta - alpha (negative descending)
  double alpha_rad = 0.0;
  double pitch_rad = 0.0;
  double speed_m_s = 0.0;
  double depth_rate_m_s = 0.0;  // + descending
  double horizontal_speed_m_s = 0.0;
  double net_buoyancy_kg = 0.0;  // + heavy
};

struct SteadyGlideResult {
  std::optional<SteadyGlide> glide;
  std::string error;  // why there is no glide (e.g. steeper than possible)
};

// Steady glide with the given glide path magnitude (deg, > 0) and net
// buoyancy (kg: + heavy = descending, - light = climbing), from the force
// balance alone. Of the two angles of attack that give the same path, the
// one with less drag (the flight branch of paper 000 Fig. 12).
SteadyGlideResult steady_glide_for_path(const Hydrodynamics& hydro, double density_kg_m3, double glide_path_deg,
                                        double net_buoyancy_kg, double gravity_m_s2 = 9.81);

// Steady glide at a given pitch (rad) and net buoyancy (kg), from the force
// balance alone (the pitch is taken as measured, as flight-model fits to real
// data do). No glide if the pitch is shallower than the best glide allows or
// points the wrong way for the sign of the buoyancy.
SteadyGlideResult steady_glide_for_pitch(const Hydrodynamics& hydro, double density_kg_m3, double pitch_rad,
                                         double net_buoyancy_kg, double gravity_m_s2 = 9.81);

// The same for many samples of one vehicle: the flight branches (zero-lift
// angle, best glide) are found once, so one solve costs ~1 us.
class PitchGlideSolver {
 public:
  explicit PitchGlideSolver(const Hydrodynamics& hydro);
  SteadyGlideResult solve(double density_kg_m3, double pitch_rad, double net_buoyancy_kg,
                          double gravity_m_s2 = 9.81) const;

 private:
  // One pass on a speed-independent polar whose best glide is at t_best.
  SteadyGlideResult solve_on(const Hydrodynamics& hydro, double t_best, double density_kg_m3, double pitch_rad,
                             double net_buoyancy_kg, double gravity_m_s2) const;
  Hydrodynamics hydro_;
  double alpha0_;
  double t_best_[2];  // descending, climbing
  // With the Reynolds term: the best glides of the polar at the factor of
  // kBracketSpeedMS, faster than gliders fly (the bracket of every pass).
  static constexpr double kBracketSpeedMS = 3.0;
  double low_factor_ = 1.0;
  mutable double t_best_low_[2];  // 0: not yet found
};

// Shallowest possible glide path (deg) descending (+1) or climbing (-1): at
// the angle of attack of the best lift-to-drag ratio.
double min_glide_path_deg(const Hydrodynamics& hydro, int direction = 1);

// True if, at this pitch (rad, - nose down), the polar holds a steady glide
// on its back side besides the flight branch: the glide-path balance
// atan(D/L) = |pitch| + |alpha| has more than one root - a stalled state at a
// large angle of attack (the blend into cross-flow) that a glider with too
// little lift for its pitch can settle on.
bool has_stall_glide(const Hydrodynamics& hydro, double pitch_rad);

// Forward problem: where does the vehicle settle with this ballast and these
// moving-mass positions (fin centred, still water at `depth_m`)? Solves force
// and moment balance with the full model's terms (GliderDynamics::evaluate).
SteadyGlideResult solve_equilibrium(const GliderDynamics& dynamics, const MassInputs& masses, double depth_m);

// The battery position that balances the pitching moment of a given steady
// glide, the other masses as in `masses` (the moment is affine in it).
double battery_for_glide(const GliderDynamics& dynamics, const SteadyGlide& glide, MassInputs masses, double depth_m);

// Inverse problem: the ballast and battery position that fly the given glide
// path (deg, magnitude) with the given net buoyancy (kg, sign = direction).
struct Trim {
  SteadyGlide glide;
  double pumped_volume_m3 = 0.0;
  double battery_pos_m = 0.0;
  bool within_limits = false;  // inside the pump range and the slide travel
  std::string note;            // which limit is exceeded
};
struct TrimResult {
  std::optional<Trim> trim;
  std::string error;
};
TrimResult solve_trim(const GliderDynamics& dynamics, double glide_path_deg, double net_buoyancy_kg, double depth_m);

}  // namespace glider::model
