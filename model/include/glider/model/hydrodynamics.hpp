// SPDX-License-Identifier: Apache-2.0
#pragma once
#include "glider/model/vehicle.hpp"

namespace glider::model {

// Force coefficients at angle of attack `alpha_rad` (any value in [-pi, pi]).
// Up to fit_valid_to_rad they are the identified polynomial fits (paper 000:
// C_L = 11.76 a + 4.6 a|a|, C_D = 0.214 + 32.3 a^2); beyond crossflow_from_rad
// a crossflow (normal-force) model, so that inflections, the surface and
// stalls stay physical; in between a smooth blend.
struct ForceCoefficients {
  double lift = 0.0;
  double drag = 0.0;
};

ForceCoefficients force_coefficients(const Hydrodynamics& h, double alpha_rad);

// The polar's slopes, which depend on the vehicle alone: the whole lift slope
// (lift_slope_per_rad) and the drag's a^2 coefficient (hull and wings'
// induced drag). A flight asks force_coefficients millions of times with one
// vehicle: taken once, they are the same numbers (the same expressions), so
// the coefficients are the same bits.
struct PolarSlopes {
  double lift_per_rad = 0.0;
  double drag_per_rad2 = 0.0;
};
PolarSlopes polar_slopes(const Hydrodynamics& h);
ForceCoefficients force_coefficients(const Hydrodynamics& h, const PolarSlopes& slopes, double alpha_rad);

// The wings' share (0 without wings), by the reference area: the lift slope
// of a swept finite wing, a_w = 2 pi AR / (2 + sqrt(AR^2 (1 + tan^2 sweep) + 4))
// (the Helmbold/DATCOM form Merckelbach et al. 2019 use in gliderflight), and
// its induced drag C_L^2 / (pi e AR), i.e. a_w^2 / (pi e AR) per rad^2; both
// times wing area / reference area.
double wing_lift_slope_per_rad(const Hydrodynamics& h);
double wing_induced_drag_per_rad2(const Hydrodynamics& h);

// The whole vehicle's lift slope at zero angle (hull cl_alpha + wings).
double lift_slope_per_rad(const Hydrodynamics& h);

// Viscous pitching moment coefficient (m), without damping and without Munk:
// cm0 + cm_alpha a inside the fit, cm_alpha sin a cos a in crossflow.
double moment_coefficient(const Hydrodynamics& h, double alpha_rad);

}  // namespace glider::model
