// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <algorithm>
#include <cmath>

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
// cd0_factor scales the zero-lift (skin-friction) drag: the Reynolds term
// skin_friction_factor at the flight's speed; 1 is the file's cd0.
ForceCoefficients force_coefficients(const Hydrodynamics& h, const PolarSlopes& slopes, double alpha_rad,
                                     double cd0_factor = 1.0);

// The skin friction's Reynolds-number term at speed V through the water:
// (V / cd0_reference_speed_m_s)^-cd0_reynolds_exponent, exactly 1 when the
// exponent is 0. Below kSkinFrictionMinSpeedMS the speed is taken as that
// (a glider at rest has no boundary layer to speak of; the drag is ~0 there
// anyway), so the factor stays finite.
constexpr double kSkinFrictionMinSpeedMS = 0.02;
double skin_friction_factor(const Hydrodynamics& h, double speed_m_s);

// The same factor for the millions of stages of a fitted flight, without a
// pow at each: the exact factor at an anchor speed (pow), and within
// kAnchorSpan of it the factor's Taylor series in d = V / V_anchor - 1 to
// d^4; a speed farther away becomes the new anchor. Successive stages fly
// nearly the same speed, so a pow is taken every few steps. Relative error
// below n(n+1)(n+2)(n+3)(n+4)/120 d^5 at |d| = 0.01: 2.5e-12 for n = 0.1,
// 2.5e-11 for n = 0.5 (the anchor depends on the speeds asked before: the
// same sequence gives the same bits; restart() forgets them, so a flight
// restarted at its first stage is a function of its own speeds alone).
class SkinFrictionFactor {
 public:
  static constexpr double kAnchorSpan = 0.01;
  explicit SkinFrictionFactor(const Hydrodynamics& h);
  // Inline: it sits in every stage of every flight (as a call, 4 % of a 24 h
  // log's diagnosis).
  double operator()(double speed_m_s) const {
    if (exponent_ == 0.0) return 1.0;
    const double v = std::max(speed_m_s, kSkinFrictionMinSpeedMS);
    const double d = v * anchor_inverse_ - 1.0;
    if (std::abs(d) <= kAnchorSpan) return anchor_factor_ * (1.0 + d * (c1_ + d * (c2_ + d * (c3_ + d * c4_))));
    return reanchor(v);
  }
  // No anchor: the next speed asked becomes one (as right after construction).
  void restart() const {
    anchor_inverse_ = 0.0;
    anchor_factor_ = 1.0;
  }

 private:
  double reanchor(double v) const;  // the exact factor at v, v the new anchor
  double exponent_ = 0.0, reference_m_s_ = 1.0;
  double c1_ = 0.0, c2_ = 0.0, c3_ = 0.0, c4_ = 0.0;  // (1 + d)^-n's Taylor coefficients
  mutable double anchor_inverse_ = 0.0, anchor_factor_ = 1.0;
};

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
