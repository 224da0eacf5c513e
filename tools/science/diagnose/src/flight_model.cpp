// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/flight_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glider/model/dynamics.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Plausible ranges: a glider a kilogram off trim could not fly its yos;
// hull compressibility of 1.5e-9 /Pa would be a 0.15 % volume change per
// 100 m, five times a soft Seaglider hull (~3e-10 /Pa, Eriksen et al. 2001);
// thermal expansion 3e-4 /K is four times Seaglider's therm_expan; the
// vertical velocity's value is its mean over the log's hours, and a mean of
// 2 cm/s is 72 m of water rising or sinking every hour for hours (internal
// waves average out; convective plumes reach 0.1 m/s but sink between rising
// water): beyond, it stands in for a buoyancy offset; a pump lag beyond two
// minutes is a broken pump, not a lag; a lift slope a third or three times
// the vehicle's is another wing, not a change of it; a depth sensor ten
// seconds late (a sixth of a turn) is a broken clock, not a lag.
const std::array<EffectInfo, kEffectCount> kInfo{{
    {"buoyancy_offset", "g", 0.0, 20.0, -1000.0, 1000.0},
    {"drag_change", "ratio", 1.0, 0.1, 0.3, 5.0},
    {"hull_compressibility", "1/Pa", 0.0, 1e-10, -1.5e-9, 1.5e-9},
    {"thermal_expansion", "1/K", 0.0, 1e-5, -3e-4, 3e-4},
    {"vertical_water_velocity", "m/s", 0.0, 0.01, -0.02, 0.02},
    {"water_density", "kg/m^3", 0.0, 1.0, -40.0, 40.0},
    {"pitch_trim_offset", "in", 0.0, 0.01, -2.0, 2.0},
    {"pump_lag", "s", 0.0, 5.0, -120.0, 120.0},
    {"lift_change", "ratio", 1.0, 0.1, 0.3, 3.0},
    {"depth_lag", "s", 0.0, 1.0, -10.0, 10.0},
}};

}  // namespace

model::VehicleParams apply(model::VehicleParams v, const EffectValues& x, double log_temperature_c) {
  v.buoyancy_offset_kg += x[0] * 1e-3;
  v.hydro.cd0 *= x[1];
  v.hull_compressibility_per_pa += x[2];
  // The nominal's a0 (T - T0) plus the effect's a (T - T_log) is one
  // expansion (a0 + a)(T - T0') with T0' = (a0 T0 + a T_log) / (a0 + a):
  // T_log itself for a vehicle without a nominal expansion.
  const double a0 = v.hull_thermal_expansion_per_k, a = x[3];
  if (a != 0.0 && std::isfinite(log_temperature_c) && a0 + a != 0.0) {
    v.hull_reference_temperature_c = (a0 * v.hull_reference_temperature_c + a * log_temperature_c) / (a0 + a);
  }
  v.hull_thermal_expansion_per_k = a0 + a;
  v.battery.x_at_zero_m += in_to_m(x[6]);  // pitch trim: the battery's zero moves forward
  v.ballast.lag_s += std::abs(x[7]);       // a lag has no sign: |value| keeps the fit smooth through 0
  // Lift: the hull's slope and the wings' share scale alike (as more or less
  // wing would: its induced drag with it).
  v.hydro.cl0 *= x[8];
  v.hydro.cl_alpha *= x[8];
  v.hydro.cl_alpha_abs_alpha *= x[8];
  v.hydro.wing_area_m2 *= x[8];
  return v;
}

const EffectInfo& info(Effect effect) { return kInfo[static_cast<std::size_t>(effect)]; }
Effect effect_from_index(std::size_t index) { return static_cast<Effect>(index); }

bool plausible(Effect effect, double value) {
  const EffectInfo& i = info(effect);
  return value >= i.plausible_min && value <= i.plausible_max;
}

EffectValues nominal_values() {
  EffectValues x{};
  for (std::size_t i = 0; i < kEffectCount; ++i) x[i] = kInfo[i].nominal;
  return x;
}

FlightModel::FlightModel(const model::VehicleParams& nominal, const Observations& observations)
    : nominal_(nominal), obs_(observations) {}

double VerticalVelocityProfile::at(double depth_m) const {
  if (w_m_s.empty()) return 0.0;
  return w_m_s[bin(depth_m)];
}

std::size_t VerticalVelocityProfile::bin(double depth_m) const {
  const double position = (depth_m - first_m) / bin_m;
  const long index = std::clamp(static_cast<long>(std::floor(position)), 0L, static_cast<long>(w_m_s.size()) - 1);
  return static_cast<std::size_t>(index);
}

bool flyable(const EffectValues& x) {
  return x[static_cast<std::size_t>(Effect::kDragChange)] > 0.0 &&
         x[static_cast<std::size_t>(Effect::kLiftChange)] > 0.0;
}

void FlightModel::predict(const EffectValues& x, bool use_ctd_density, std::span<const std::size_t> samples,
                          std::vector<double>& out, const VerticalVelocityProfile* profile) const {
  glide(x, use_ctd_density, samples, out, profile, false);
}

void FlightModel::predict_speed(const EffectValues& x, bool use_ctd_density, std::span<const std::size_t> samples,
                                std::vector<double>& out) const {
  glide(x, use_ctd_density, samples, out, nullptr, true);
}

void FlightModel::glide(const EffectValues& x, bool use_ctd_density, std::span<const std::size_t> samples,
                        std::vector<double>& out, const VerticalVelocityProfile* profile, bool speed) const {
  out.assign(samples.size(), kNaN);
  if (!flyable(x)) return;  // no negative drag or lift
  // A negative compressibility relative to nominal is allowed: the model's
  // water is incompressible, so "lighter with depth" is a real possibility.
  const model::VehicleParams v = apply(nominal_, x, obs_.track.median_temperature_c);
  const model::GliderDynamics dynamics(v, model::still_water(v.trim_density_kg_m3));
  const model::PitchGlideSolver solver(v.hydro);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const std::size_t i = samples[k];
    model::WaterSample water;
    water.density_kg_m3 =
        use_ctd_density && std::isfinite(obs_.density_kg_m3[i]) ? obs_.density_kg_m3[i] : v.trim_density_kg_m3 + x[5];
    water.temperature_c = std::isfinite(obs_.temperature_c[i]) ? obs_.temperature_c[i] : v.hull_reference_temperature_c;
    model::MassInputs masses;
    masses.pumped_volume_m3 = cc_to_m3(obs_.ballast_cc[i]);
    const double m0 = dynamics.net_buoyancy_kg(obs_.depth_m[i], water, masses);
    const auto steady = solver.solve(water.density_kg_m3, obs_.pitch_rad[i], m0);
    const double w = profile != nullptr ? profile->at(obs_.depth_m[i]) : x[4];
    if (steady.glide) out[k] = speed ? steady.glide->speed_m_s : steady.glide->depth_rate_m_s + w;
  }
}

double FlightModel::equilibrium_pitch_rad(std::size_t i, const EffectValues& values) const {
  if (!std::isfinite(obs_.battpos_in[i])) return kNaN;
  const model::VehicleParams v = apply(nominal_, values, obs_.track.median_temperature_c);
  const model::GliderDynamics dynamics(v, model::still_water(v.trim_density_kg_m3));
  model::MassInputs masses;
  masses.pumped_volume_m3 = cc_to_m3(obs_.ballast_cc[i]);
  masses.battery_pos_m = in_to_m(obs_.battpos_in[i]);
  const auto eq = model::solve_equilibrium(dynamics, masses, obs_.depth_m[i]);
  return eq.glide ? eq.glide->pitch_rad : kNaN;
}

double FlightModel::required_battpos_in(std::size_t i, const EffectValues& values, bool use_ctd_density) const {
  const model::VehicleParams v = apply(nominal_, values, obs_.track.median_temperature_c);
  const model::GliderDynamics dynamics(v, model::still_water(v.trim_density_kg_m3));
  model::MassInputs masses;
  masses.pumped_volume_m3 = cc_to_m3(obs_.ballast_cc[i]);
  model::WaterSample water;
  water.density_kg_m3 = use_ctd_density && std::isfinite(obs_.density_kg_m3[i]) ? obs_.density_kg_m3[i]
                                                                                : v.trim_density_kg_m3 + values[5];
  water.temperature_c = std::isfinite(obs_.temperature_c[i]) ? obs_.temperature_c[i] : v.hull_reference_temperature_c;
  const double m0 = dynamics.net_buoyancy_kg(obs_.depth_m[i], water, masses);
  const auto glide = model::steady_glide_for_pitch(v.hydro, water.density_kg_m3, obs_.pitch_rad[i], m0);
  if (!glide.glide) return kNaN;
  return m_to_in(model::battery_for_glide(dynamics, *glide.glide, masses, obs_.depth_m[i]));
}

double deepest_density_anomaly(std::span<const double> depth_m, std::span<const double> density_kg_m3,
                               double nominal_kg_m3) {
  double deepest = -1.0, rho = kNaN;
  for (std::size_t i = 0; i < depth_m.size(); ++i) {
    if (std::isfinite(density_kg_m3[i]) && depth_m[i] > deepest) {
      deepest = depth_m[i];
      rho = density_kg_m3[i];
    }
  }
  return rho - nominal_kg_m3;
}

double FlightModel::ctd_density_anomaly() const {
  return deepest_density_anomaly(obs_.depth_m, obs_.density_kg_m3, nominal_.trim_density_kg_m3);
}

}  // namespace glider::diagnose
