#include "glider/model/steady_glide.hpp"

#include <cmath>
#include <numbers>

#include "glider/model/hydrodynamics.hpp"

namespace glider::model {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Drag/lift ratio at positive angle of attack.
double drag_over_lift(const Hydrodynamics& h, double alpha) {
  const ForceCoefficients c = force_coefficients(h, alpha);
  return c.drag / c.lift;
}

// Angle of attack of minimum D/L within the fitted range (golden section:
// D/L is unimodal there).
double alpha_of_best_glide(const Hydrodynamics& h) {
  double lo = 1e-6;
  double hi = h.fit_valid_to_rad;
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double a = hi - ratio * (hi - lo);
    const double b = lo + ratio * (hi - lo);
    if (drag_over_lift(h, a) < drag_over_lift(h, b)) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double min_glide_path_deg(const Hydrodynamics& hydro) {
  return std::atan(drag_over_lift(hydro, alpha_of_best_glide(hydro))) / kDeg;
}

SteadyGlideResult steady_glide_for_path(const Hydrodynamics& hydro, double density_kg_m3,
                                        double glide_path_deg, double net_buoyancy_kg, double gravity_m_s2) {
  SteadyGlideResult result;
  if (!(glide_path_deg > 0.0 && glide_path_deg < 90.0)) {
    result.error = "glide path must be between 0 and 90 deg (magnitude)";
    return result;
  }
  if (net_buoyancy_kg == 0.0 || !std::isfinite(net_buoyancy_kg)) {
    result.error = "a steady glide needs a non-zero net buoyancy";
    return result;
  }
  const double a_best = alpha_of_best_glide(hydro);
  const double gamma_min = min_glide_path_deg(hydro);
  if (glide_path_deg < gamma_min) {
    result.error = "glide path shallower than the vehicle's best glide (" + std::to_string(gamma_min) + " deg)";
    return result;
  }
  // On (0, a_best] D/L falls monotonically from +inf to its minimum: bisect.
  const double target = std::tan(glide_path_deg * kDeg);
  double lo = 1e-9;
  double hi = a_best;
  for (int i = 0; i < 200 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (drag_over_lift(hydro, mid) > target ? lo : hi) = mid;
  }
  const double alpha = 0.5 * (lo + hi);
  const ForceCoefficients c = force_coefficients(hydro, alpha);
  const double weight_n = std::abs(net_buoyancy_kg) * gravity_m_s2;
  const double speed =
      std::sqrt(2.0 * weight_n / (density_kg_m3 * hydro.reference_area_m2 * std::hypot(c.lift, c.drag)));

  // Heavy: descending, xi < 0, alpha > 0. Light: the mirror image.
  const double sign = net_buoyancy_kg > 0.0 ? 1.0 : -1.0;
  SteadyGlide g;
  g.glide_path_rad = -sign * glide_path_deg * kDeg;
  g.alpha_rad = sign * alpha;
  g.pitch_rad = g.glide_path_rad + g.alpha_rad;
  g.speed_m_s = speed;
  g.depth_rate_m_s = -speed * std::sin(g.glide_path_rad);
  g.horizontal_speed_m_s = speed * std::cos(g.glide_path_rad);
  result.glide = g;
  return result;
}

}  // namespace glider::model
