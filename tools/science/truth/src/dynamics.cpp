// SPDX-License-Identifier: Apache-2.0
#include "glider/truth/dynamics.hpp"

#include <algorithm>
#include <cmath>

namespace glider::truth {
namespace {

constexpr double kMinSpeed = 0.02;     // m/s: below, the lift lag and the drag law use this speed
constexpr double kActuatorGain = 5.0;  // 1/s: how sharply an actuator stops at its target (rate-limited before)

double move_toward(double x, double target, double rate) {
  return std::clamp(kActuatorGain * (target - x), -rate, rate);
}

double blend(double a, double from, double to) {
  if (a <= from) return 0.0;
  if (a >= to) return 1.0;
  const double s = (a - from) / (to - from);
  return s * s * (3.0 - 2.0 * s);
}

struct Body {
  double m, xg, zg, iy;
};

Body body(const Vehicle& v, double battery_m) {
  Body b;
  b.m = v.mass_kg();
  const double xb = v.battery_x_at_zero_m + battery_m;
  b.xg = (v.offset_kg * v.offset_x_m + v.battery_kg * xb) / b.m;
  b.zg = (v.offset_kg * v.offset_z_m + v.battery_kg * v.battery_z_m) / b.m;
  b.iy = v.hull_inertia_kg_m2 + v.offset_kg * (v.offset_x_m * v.offset_x_m + v.offset_z_m * v.offset_z_m) +
         v.battery_kg * (xb * xb + v.battery_z_m * v.battery_z_m);
  return b;
}

}  // namespace

void FinHistory::add(double t, double fin) {
  if (!time_s.empty() && t <= time_s.back()) return;
  time_s.push_back(t);
  fin_rad.push_back(fin);
}

double FinHistory::at(double t) const {
  if (time_s.empty()) return 0.0;
  if (t <= time_s.front()) return fin_rad.front();
  if (t >= time_s.back()) return fin_rad.back();
  const auto it = std::upper_bound(time_s.begin(), time_s.end(), t);
  const std::size_t j = static_cast<std::size_t>(it - time_s.begin());
  const double w = (t - time_s[j - 1]) / (time_s[j] - time_s[j - 1]);
  return fin_rad[j - 1] + w * (fin_rad[j] - fin_rad[j - 1]);
}

Dynamics::Forces Dynamics::forces(double t, const State& y) const {
  const Vehicle& v = vehicle;
  const Hydro& h = v.hydro;
  Forces f;
  f.speed_m_s = std::hypot(y[kSurge], y[kHeave]);
  f.alpha_rad = std::atan2(y[kHeave], y[kSurge]);
  const double z = y[kDepth];
  f.density_kg_m3 = water.density_kg_m3(z, t);
  const double pressure_pa = 1025.0 * kGravity * std::max(0.0, z);
  const double hull_volume =
      v.volume_m3() * (1.0 - v.hull_compressibility_per_pa * pressure_pa +
                       v.thermal_expansion_per_k * (water.temperature_c(z, t) - v.reference_temperature_c));
  f.net_weight_n = (v.mass_kg() - f.density_kg_m3 * (hull_volume + y[kDisplaced])) * kGravity;
  const double a = f.alpha_rad, abs_a = std::abs(a);
  const double speed = std::max(f.speed_m_s, kMinSpeed);
  const double s = blend(abs_a, h.fit_valid_to_rad, h.crossflow_from_rad);
  const double normal = h.cn90 * std::sin(a) * std::abs(std::sin(a));
  const double cl_fit = h.cl0 + h.cl_alpha * a + h.cl_alpha_abs_alpha * a * abs_a;
  f.lift_coefficient = (1.0 - s) * cl_fit + s * normal * std::cos(a);
  const double cd_fit =
      h.cd0 * std::pow(speed / v.unmodelled.drag_reference_speed_m_s, -v.unmodelled.drag_reynolds_exponent) +
      h.cd_alpha2 * a * a;
  f.drag_coefficient = (1.0 - s) * cd_fit + s * (h.cd0 + std::abs(normal * std::sin(a)));
  return f;
}

void Dynamics::operator()(double t, const State& y, State& d) const {
  const Vehicle& v = vehicle;
  const Hydro& h = v.hydro;
  const Unmodelled& um = v.unmodelled;
  const Forces f = forces(t, y);
  const double u = y[kSurge], w = y[kHeave], q = y[kPitchRate], theta = y[kPitch];
  const double speed = std::max(f.speed_m_s, kMinSpeed);
  const double rho = f.density_kg_m3;
  const Body b = body(v, y[kBattery]);
  const double st = std::sin(theta), ct = std::cos(theta);

  // Lift: the quasi-steady coefficient with the pitch rate's part, lagged.
  const double lift_target = f.lift_coefficient + um.cl_q * q * um.chord_m / speed;
  d[kLift] = (lift_target - y[kLift]) * speed / (um.lift_lag_chords * um.chord_m);
  const double cl = y[kLift], cd = f.drag_coefficient;
  const double dyn = 0.5 * rho * f.speed_m_s * f.speed_m_s * h.area_m2;
  const double sa = f.speed_m_s > 0.0 ? w / f.speed_m_s : 0.0, ca = f.speed_m_s > 0.0 ? u / f.speed_m_s : 1.0;
  const double x_hydro = dyn * (cl * sa - cd * ca);
  const double z_hydro = dyn * (-cl * ca - cd * sa);
  const double m_hydro =
      dyn * (h.cm0_m + h.cm_alpha_m * f.alpha_rad) + 0.5 * rho * h.area_m2 * f.speed_m_s * h.cmq_m2 * q;

  // Weight less buoyancy at the centre of buoyancy; the pumped volume's
  // buoyancy acts at the pump (nose), the weight at the centre of gravity.
  const double weight = b.m * kGravity;
  const double net = f.net_weight_n;
  const double x_static = -net * st, z_static = net * ct;
  const double m_static = -weight * (b.zg * st + b.xg * ct) + rho * kGravity * y[kDisplaced] * v.ballast_x_m * ct;

  const double mx = v.added_x_kg, mz = v.added_z_kg;
  const double r1 = x_hydro + x_static - b.m * (q * w - b.xg * q * q) - mz * w * q;
  const double r2 = z_hydro + z_static + b.m * (q * u + b.zg * q * q) + mx * u * q;
  const double r3 = m_hydro + m_static + (mz - mx) * u * w - b.m * (b.zg * w * q + b.xg * u * q);
  // [m+mx, 0, m zg; 0, m+mz, -m xg; m zg, -m xg, Iy+Ia] (u', w', q') = r
  const double a11 = b.m + mx, a13 = b.m * b.zg, a22 = b.m + mz, a23 = -b.m * b.xg, a33 = b.iy + v.added_inertia_kg_m2;
  const double det = a11 * (a22 * a33 - a23 * a23) - a13 * (a13 * a22);
  const double c11 = a22 * a33 - a23 * a23, c12 = a13 * a23, c13 = -a13 * a22;
  const double c22 = a11 * a33 - a13 * a13, c23 = -a11 * a23, c33 = a11 * a22;
  d[kSurge] = (c11 * r1 + c12 * r2 + c13 * r3) / det;
  d[kHeave] = (c12 * r1 + c22 * r2 + c23 * r3) / det;
  d[kPitchRate] = (c13 * r1 + c23 * r2 + c33 * r3) / det;
  d[kPitch] = q;

  const double z = y[kDepth];
  d[kDepth] = -u * st + w * ct + water.vertical_velocity_m_s(z, t);
  double current_east = 0.0, current_north = 0.0;
  water.current_m_s(z, current_east, current_north);
  const double horizontal = u * ct + w * st;
  d[kNorth] = horizontal * std::cos(y[kHeading]) + current_north;
  d[kEast] = horizontal * std::sin(y[kHeading]) + current_east;

  // Yaw: tau1 tau2 r'' + (tau1 + tau2) r' + r = target.
  const HeadingParams& hd = v.heading;
  const double fin_late = fin_history != nullptr && yaw_delay_s > 0.0 ? fin_history->at(t - yaw_delay_s) : y[kFin];
  const double alpha_effective = h.cl_alpha != 0.0 ? cl / h.cl_alpha : 0.0;
  const double yaw_target = f.speed_m_s * (hd.fin_yaw_gain_per_m * fin_effectiveness * fin_late +
                                           hd.roll_yaw_gain_per_m * alpha_effective * std::sin(y[kRoll])) +
                            targets.yaw_disturbance_rad_s;
  const double tau1 = hd.yaw_time_constant_s, tau2 = um.yaw_second_pole_s;
  d[kHeading] = y[kYawRate];
  d[kYawRate] = y[kYawAcceleration];
  d[kYawAcceleration] = (yaw_target - y[kYawRate] - (tau1 + tau2) * y[kYawAcceleration]) / (tau1 * tau2);
  d[kRoll] = (hd.roll_rad + um.fin_roll_per_rad * y[kFin] - y[kRoll]) / um.roll_time_constant_s;

  d[kPiston] = move_toward(y[kPiston], targets.piston_m3, v.pump_rate_m3_s);
  d[kDisplaced] = v.pump_lag_s > 0.0 ? (y[kPiston] - y[kDisplaced]) / v.pump_lag_s : d[kPiston];
  d[kBattery] = move_toward(y[kBattery], targets.battery_m, v.battery_rate_m_s);
  d[kFin] = move_toward(y[kFin], targets.fin_rad, hd.fin_rate_rad_s);
  d[kSensedDepth] = depth_sensor_lag_s > 0.0 ? (z - y[kSensedDepth]) / depth_sensor_lag_s : d[kDepth];
}

double kinetic_energy(const Vehicle& v, const State& y) {
  const Body b = body(v, y[kBattery]);
  const double u = y[kSurge], w = y[kHeave], q = y[kPitchRate];
  // 1/2 nu' M nu with the rigid-body and added-mass matrix above.
  return 0.5 * ((b.m + v.added_x_kg) * u * u + (b.m + v.added_z_kg) * w * w + (b.iy + v.added_inertia_kg_m2) * q * q) +
         b.m * b.zg * u * q - b.m * b.xg * w * q;
}

}  // namespace glider::truth
