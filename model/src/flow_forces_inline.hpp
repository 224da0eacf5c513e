// SPDX-License-Identifier: Apache-2.0
#pragma once
// The force coefficients and the flow forces (hydrodynamics.hpp,
// dynamics.hpp) as inline functions, private to the model library: the
// prescribed-pitch model asks them at every stage of every flight of a
// diagnosis (tens of millions of times on a 24 h log), where the calls, the
// whole FlowForces struct returned through memory and the moment's branch
// cost as much as the arithmetic. hydrodynamics.cpp and dynamics.cpp define
// the public functions through these, so there is one copy of each formula;
// the same expressions in the same order (no FMA contraction on this build),
// so inlined or not, the same bits.
#include <algorithm>
#include <cmath>

#include "glider/model/dynamics.hpp"
#include "glider/model/hydrodynamics.hpp"

namespace glider::model::detail {

// 1 inside the fit's range, 0 in the crossflow range, C1-smooth in between.
inline double fit_weight(const Hydrodynamics& h, double alpha_rad) {
  const double a = std::abs(alpha_rad);
  if (a <= h.fit_valid_to_rad) return 1.0;
  if (a >= h.crossflow_from_rad) return 0.0;
  const double u = (a - h.fit_valid_to_rad) / (h.crossflow_from_rad - h.fit_valid_to_rad);
  return 1.0 - u * u * (3.0 - 2.0 * u);
}

inline ForceCoefficients force_coefficients(const Hydrodynamics& h, const PolarSlopes& slopes, double alpha_rad,
                                            double cd0_factor) {
  const double cd0 = h.cd0 * cd0_factor;
  const double w = detail::fit_weight(h, alpha_rad);
  ForceCoefficients fit{};
  if (w > 0.0) {
    // Beyond its range the polynomial is evaluated at the range's edge (it is
    // then only a fading part of the blend).
    const double a = std::clamp(alpha_rad, -h.crossflow_from_rad, h.crossflow_from_rad);
    fit.lift = h.cl0 + slopes.lift_per_rad * a + h.cl_alpha_abs_alpha * a * std::abs(a);
    fit.drag = cd0 + slopes.drag_per_rad2 * a * a;
  }
  if (w >= 1.0) return fit;
  // Crossflow: normal force ~ sin a |sin a|, axial (skin) force ~ cos a |cos a|,
  // rotated into lift (normal to the flow) and drag (along the flow).
  const double s = std::sin(alpha_rad);
  const double c = std::cos(alpha_rad);
  const double normal = h.crossflow_cn90 * s * std::abs(s);
  const double axial = cd0 * c * std::abs(c);
  const ForceCoefficients cross{normal * c - axial * s, normal * s + axial * c};
  return {w * fit.lift + (1.0 - w) * cross.lift, w * fit.drag + (1.0 - w) * cross.drag};
}

// atan2(v3, v1) for the prescribed-pitch stage, whose flights glide at a few
// degrees of attack: there atan(t), t = v3 / v1 with |t| <= 1/4 (14 deg), is
// its Taylor series to t^23 (the first term left out is below t * 6e-18, far
// under an ulp), summed in Estrin's scheme so that the terms do not wait on
// each other; outside, glibc's atan2. The stage's chain of dependent operations
// sets a flight's time, and glibc's atan2 (with its rounding-mode save and
// errno wrapper) was about a sixth of it (docs/science.md, speed4). Within a
// few ulps of atan2, not the same bits.
inline double small_angle_atan2(double v3, double v1) {
  constexpr double kMaxRatio = 0.25;
  if (!(v1 > 0.0) || !(std::abs(v3) <= kMaxRatio * v1)) return std::atan2(v3, v1);
  const double t = v3 / v1;
  const double s = t * t;
  const double s2 = s * s;
  const double s4 = s2 * s2;
  const double s8 = s4 * s4;
  // (-1)^k / (2k + 1), k = 0..11, in pairs.
  const double q0 = 1.0 + (-1.0 / 3.0) * s;
  const double q1 = 1.0 / 5.0 + (-1.0 / 7.0) * s;
  const double q2 = 1.0 / 9.0 + (-1.0 / 11.0) * s;
  const double q3 = 1.0 / 13.0 + (-1.0 / 15.0) * s;
  const double q4 = 1.0 / 17.0 + (-1.0 / 19.0) * s;
  const double q5 = 1.0 / 21.0 + (-1.0 / 23.0) * s;
  const double r0 = q0 + q1 * s2;
  const double r1 = q2 + q3 * s2;
  const double r2 = q4 + q5 * s2;
  return t * ((r0 + r1 * s4) + r2 * s8);
}

// The flow forces at a known angle of attack alpha_rad = atan2(v3, v1).
inline FlowForces flow_forces_at_angle(const Hydrodynamics& h, const PolarSlopes& slopes, double water_density,
                                       double v1, double v3, double speed_m_s, double alpha_rad, bool with_moment,
                                       double cd0_factor) {
  FlowForces out;
  out.speed_m_s = speed_m_s;
  out.alpha_rad = alpha_rad;
  if (!(out.speed_m_s > 0.0)) return out;
  const ForceCoefficients c = detail::force_coefficients(h, slopes, out.alpha_rad, cd0_factor);
  const double dyn = 0.5 * water_density * h.reference_area_m2 * out.speed_m_s * out.speed_m_s;
  out.lift_coefficient = c.lift;
  out.lift_n = dyn * c.lift;
  out.drag_n = dyn * c.drag;
  const double cos_a = v1 / out.speed_m_s;
  const double sin_a = v3 / out.speed_m_s;
  out.f1 = out.lift_n * sin_a - out.drag_n * cos_a;
  out.f3 = -out.lift_n * cos_a - out.drag_n * sin_a;
  if (with_moment) out.moment_nm = dyn * moment_coefficient(h, out.alpha_rad);
  return out;
}

inline FlowForces flow_forces_at_speed(const Hydrodynamics& h, const PolarSlopes& slopes, double water_density,
                                       double v1, double v3, double speed_m_s, bool with_moment, double cd0_factor) {
  return flow_forces_at_angle(h, slopes, water_density, v1, v3, speed_m_s, std::atan2(v3, v1), with_moment, cd0_factor);
}

}  // namespace glider::model::detail
