// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/water.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glider::truth {
namespace {
double uniform(std::mt19937_64& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
double smooth_step(double x) { return 0.5 * (1.0 + std::tanh(x)); }
}  // namespace

double Water::heave_m(double z, double t_s) const {
  const double omega = 2.0 * std::numbers::pi / wave_period_s;
  return wave_w_m_s / omega * std::sin(std::numbers::pi * z / bottom_m) * std::sin(omega * t_s + wave_phase_rad);
}

double Water::temperature_c(double z, double t_s) const {
  const double zi = z - heave_m(z, t_s);  // the water here came from zi
  return deep_temperature_c + (surface_temperature_c - deep_temperature_c) *
                                  (1.0 - smooth_step((zi - thermocline_m) / thermocline_thickness_m));
}

double Water::salinity(double z, double t_s) const {
  const double zi = z - heave_m(z, t_s);
  return surface_salinity +
         (deep_salinity - surface_salinity) * smooth_step((zi - thermocline_m) / thermocline_thickness_m);
}

double Water::density_kg_m3(double z, double t_s) const {
  const double dt = temperature_c(z, t_s) - 10.0;
  const double ds = salinity(z, t_s) - 35.0;
  // Coefficients near 10 degC, 35 g/kg (thermal 1.7e-4 /K rising 1e-5 /K
  // per K, haline 7.6e-4).
  return 1027.0 * (1.0 - 1.7e-4 * dt - 5e-6 * dt * dt + 7.6e-4 * ds) + compression_kg_m3_per_m * std::max(0.0, z) +
         density_offset_kg_m3;
}

double Water::hidden_vertical_velocity_m_s(double z) const {
  if (hidden_w_m_s == 0.0) return 0.0;
  if (hidden_w_to_m <= hidden_w_from_m)
    return hidden_w_m_s * std::sin(std::numbers::pi * std::clamp(z / bottom_m, 0.0, 1.0));
  constexpr double kEdgeM = 4.0;
  return hidden_w_m_s * smooth_step((z - hidden_w_from_m) / kEdgeM) * (1.0 - smooth_step((z - hidden_w_to_m) / kEdgeM));
}

double Water::vertical_velocity_m_s(double z, double t_s) const {
  const double omega = 2.0 * std::numbers::pi / wave_period_s;
  const double wave = wave_w_m_s * std::sin(std::numbers::pi * std::clamp(z / bottom_m, 0.0, 1.0)) *
                      std::cos(omega * t_s + wave_phase_rad);
  return wave + hidden_vertical_velocity_m_s(z);
}

void Water::current_m_s(double z, double& east, double& north) const {
  const double speed = std::hypot(current_east_m_s, current_north_m_s);
  const double factor = speed > 0.0 ? std::max(-1.0, 1.0 - shear_per_s * std::max(0.0, z) / speed) : 0.0;
  east = current_east_m_s * factor;
  north = current_north_m_s * factor;
}

Water draw_water(std::mt19937_64& rng, double dive_to_m) {
  Water w;
  // At most ~2.5 kg/m^3 from top to bottom: a +-230 cc pump trimmed for
  // the middle still has ~140 g each way (a stronger one is another mission).
  w.surface_temperature_c = uniform(rng, 12.0, 20.0);
  w.deep_temperature_c = uniform(rng, 6.0, 10.0);
  w.thermocline_m = uniform(rng, 0.25, 0.6) * dive_to_m;
  w.thermocline_thickness_m = uniform(rng, 5.0, 15.0);
  w.surface_salinity = uniform(rng, 34.8, 35.0);
  w.deep_salinity = uniform(rng, 35.0, 35.2);
  w.bottom_m = dive_to_m * uniform(rng, 1.2, 2.0);
  w.wave_w_m_s = uniform(rng, 0.002, 0.006);
  w.wave_period_s = uniform(rng, 900.0, 3600.0);
  w.wave_phase_rad = uniform(rng, 0.0, 2.0 * std::numbers::pi);
  const double current = uniform(rng, 0.0, 0.3), direction = uniform(rng, 0.0, 2.0 * std::numbers::pi);
  w.current_east_m_s = current * std::sin(direction);
  w.current_north_m_s = current * std::cos(direction);
  w.shear_per_s = uniform(rng, 0.0, 0.002);
  return w;
}

}  // namespace glider::truth
