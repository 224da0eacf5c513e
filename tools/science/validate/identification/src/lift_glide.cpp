// SPDX-License-Identifier: Apache-2.0
#include "glider/identification/lift_glide.hpp"

#include <algorithm>
#include <cmath>

#include "glider/model/hydrodynamics.hpp"
#include "glider/model/root_finding.hpp"

namespace glider::identification {

LiftModel lift_model_of(const model::VehicleParams& vehicle) {
  LiftModel lift;
  lift.hydro = vehicle.hydro;
  lift.density_kg_m3 = vehicle.trim_density_kg_m3;
  return lift;
}

std::optional<GlideFromLift> glide_from_lift(const LiftModel& lift, const SteadyGlideSample& sample,
                                             double buoyancy_offset_kg) {
  const double m0 = sample.ballast_net_kg + buoyancy_offset_kg;
  const double rate = sample.depth_rate_m_s;
  const double theta = sample.pitch_rad;
  // A descending glide needs a heavy vehicle and lift pointing up (a > 0),
  // a climbing one the mirror image.
  const double direction = rate > 0.0 ? 1.0 : -1.0;
  if (rate == 0.0 || !(m0 * direction > 0.0) || !std::isfinite(rate) || !std::isfinite(theta)) return std::nullopt;
  const double rho_area = lift.density_kg_m3 * lift.hydro.reference_area_m2;
  const double g = lift.gravity_m_s2;
  auto residual = [&](double a) {
    const double v = rate / std::sin(a - theta);
    return 0.5 * rho_area * model::force_coefficients(lift.hydro, a).lift * v * v - m0 * g * std::cos(theta - a);
  };
  // Search |a| in (0, fit range]; the flow must come from ahead of the path:
  // direction * (a - theta) > 0, else eq. 10 has no positive speed.
  const double a_max = lift.hydro.fit_valid_to_rad > 0.0 ? lift.hydro.fit_valid_to_rad : 0.25;
  const double t_min = std::max(0.0, direction * theta) + 1e-9;
  if (!(t_min < a_max)) return std::nullopt;
  const double lo = direction * t_min;
  const double hi = direction * a_max;
  const double r_lo = residual(lo);
  const double r_hi = residual(hi);
  if (!((r_lo < 0.0) != (r_hi < 0.0))) return std::nullopt;  // no sign change (or NaN)
  GlideFromLift glide;
  glide.alpha_rad =
      model::bracketed_root(residual, std::min(lo, hi), std::max(lo, hi), lo < hi ? r_lo : r_hi, lo < hi ? r_hi : r_lo);
  glide.speed_m_s = rate / std::sin(glide.alpha_rad - theta);
  glide.net_buoyancy_kg = m0;
  glide.glide_path_rad = theta - glide.alpha_rad;
  glide.lift_coefficient = model::force_coefficients(lift.hydro, glide.alpha_rad).lift;
  const double dynamic_force_n = 0.5 * rho_area * glide.speed_m_s * glide.speed_m_s;
  glide.drag_coefficient = -m0 * g * std::sin(glide.glide_path_rad) / dynamic_force_n;
  return glide;
}

}  // namespace glider::identification
