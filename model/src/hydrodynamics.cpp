// SPDX-License-Identifier: Apache-2.0
#include "glider/model/hydrodynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "flow_forces_inline.hpp"

namespace glider::model {
namespace {

// Lift slope of the wing by its own area.
double wing_slope_by_wing_area(const Hydrodynamics& h) {
  // Remembered for the last wing asked about: force_coefficients needs it at
  // every stage of every flight, and its tan and sqrt were a fifth of a
  // diagnosis's CPU (perf, comet-2016). The same expression on the same
  // inputs: the same bits.
  thread_local double last_ar = std::numeric_limits<double>::quiet_NaN();
  thread_local double last_sweep = std::numeric_limits<double>::quiet_NaN();
  thread_local double last_slope = 0.0;
  if (h.wing_aspect_ratio == last_ar && h.wing_sweep_rad == last_sweep) return last_slope;
  const double ar = h.wing_aspect_ratio;
  const double tan_sweep = std::tan(h.wing_sweep_rad);
  last_slope = 2.0 * std::numbers::pi * ar / (2.0 + std::sqrt(ar * ar * (1.0 + tan_sweep * tan_sweep) + 4.0));
  last_ar = h.wing_aspect_ratio;
  last_sweep = h.wing_sweep_rad;
  return last_slope;
}

}  // namespace

double wing_lift_slope_per_rad(const Hydrodynamics& h) {
  if (!(h.wing_area_m2 > 0.0)) return 0.0;
  return wing_slope_by_wing_area(h) * h.wing_area_m2 / h.reference_area_m2;
}

double wing_induced_drag_per_rad2(const Hydrodynamics& h) {
  if (!(h.wing_area_m2 > 0.0)) return 0.0;
  const double a_w = wing_slope_by_wing_area(h);
  return a_w * a_w / (std::numbers::pi * h.wing_oswald_efficiency * h.wing_aspect_ratio) * h.wing_area_m2 /
         h.reference_area_m2;
}

double lift_slope_per_rad(const Hydrodynamics& h) { return h.cl_alpha + wing_lift_slope_per_rad(h); }

PolarSlopes polar_slopes(const Hydrodynamics& h) {
  return {lift_slope_per_rad(h), h.cd_alpha2 + wing_induced_drag_per_rad2(h)};
}

ForceCoefficients force_coefficients(const Hydrodynamics& h, double alpha_rad) {
  return force_coefficients(h, polar_slopes(h), alpha_rad);
}

double skin_friction_factor(const Hydrodynamics& h, double speed_m_s) {
  if (h.cd0_reynolds_exponent == 0.0) return 1.0;
  const double v = std::max(speed_m_s, kSkinFrictionMinSpeedMS);
  return std::pow(v / h.cd0_reference_speed_m_s, -h.cd0_reynolds_exponent);
}

SkinFrictionFactor::SkinFrictionFactor(const Hydrodynamics& h)
    : exponent_(h.cd0_reynolds_exponent), reference_m_s_(h.cd0_reference_speed_m_s) {
  const double n = exponent_;
  c1_ = -n;
  c2_ = -c1_ * (n + 1.0) / 2.0;
  c3_ = -c2_ * (n + 2.0) / 3.0;
  c4_ = -c3_ * (n + 3.0) / 4.0;
}

double SkinFrictionFactor::reanchor(double v) const {
  anchor_factor_ = std::pow(v / reference_m_s_, -exponent_);
  anchor_inverse_ = 1.0 / v;
  return anchor_factor_;
}

ForceCoefficients force_coefficients(const Hydrodynamics& h, const PolarSlopes& slopes, double alpha_rad,
                                     double cd0_factor) {
  return detail::force_coefficients(h, slopes, alpha_rad, cd0_factor);
}

double moment_coefficient(const Hydrodynamics& h, double alpha_rad) {
  const double w = detail::fit_weight(h, alpha_rad);
  const double a = std::clamp(alpha_rad, -h.crossflow_from_rad, h.crossflow_from_rad);
  const double fit = h.cm0_m + h.cm_alpha_m * a;
  if (w >= 1.0) return fit;
  // Past the fit the stabilising moment of wings and tail must not vanish
  // (else the Munk moment alone would pitch the vehicle into a deep stall):
  // it keeps the slope at small angles and the sin a cos a shape of a
  // crossflow moment, zero broadside.
  const double cross = h.cm_alpha_m * std::sin(alpha_rad) * std::cos(alpha_rad);
  return w * fit + (1.0 - w) * cross;
}

}  // namespace glider::model
