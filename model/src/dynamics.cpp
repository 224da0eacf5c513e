// SPDX-License-Identifier: Apache-2.0
#include "glider/model/dynamics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "flow_forces_inline.hpp"
#include "glider/model/hydrodynamics.hpp"

namespace glider::model {
double shear_turn_per_unit(double depth_rate_m_s, double speed_m_s) {
  // Below this speed through the water a shear's cross current is no longer
  // small against the flow the fin weathervanes in (m/s).
  constexpr double kShearMinSpeedMS = 0.1;
  return -depth_rate_m_s / std::max(speed_m_s, kShearMinSpeedMS);
}

FlowForces flow_forces(const Hydrodynamics& h, double water_density, double v1, double v3) {
  return flow_forces_at_speed(h, water_density, v1, v3, std::hypot(v1, v3));
}

FlowForces flow_forces_at_speed(const Hydrodynamics& h, double water_density, double v1, double v3, double speed_m_s,
                                bool with_moment) {
  return flow_forces_at_speed(h, polar_slopes(h), water_density, v1, v3, speed_m_s, with_moment);
}

FlowForces flow_forces_at_speed(const Hydrodynamics& h, const PolarSlopes& slopes, double water_density, double v1,
                                double v3, double speed_m_s, bool with_moment) {
  return flow_forces_at_speed(h, slopes, water_density, v1, v3, speed_m_s, with_moment,
                              skin_friction_factor(h, speed_m_s));
}

FlowForces flow_forces_at_speed(const Hydrodynamics& h, const PolarSlopes& slopes, double water_density, double v1,
                                double v3, double speed_m_s, bool with_moment, double cd0_factor) {
  return detail::flow_forces_at_speed(h, slopes, water_density, v1, v3, speed_m_s, with_moment, cd0_factor);
}

GliderDynamics::GliderDynamics(const VehicleParams& vehicle, const Environment& environment)
    : vehicle_(vehicle),
      environment_(environment),
      nominal_volume_m3_(model::displaced_volume_m3(vehicle)),
      sin_roll_offset_(std::sin(vehicle.heading.roll_offset_rad)),
      tan_roll_offset_(std::tan(vehicle.heading.roll_offset_rad)) {}

const GliderDynamics::MassProperties& GliderDynamics::MassCache::get(const GliderDynamics& dynamics,
                                                                     const MassInputs& masses, double water_density) {
  const bool same =
      valid_ && masses.pumped_volume_m3 == masses_.pumped_volume_m3 && masses.battery_pos_m == masses_.battery_pos_m &&
      masses.battery_rate_m_s == masses_.battery_rate_m_s && masses.second_pos_m == masses_.second_pos_m &&
      masses.second_rate_m_s == masses_.second_rate_m_s && water_density == water_density_;
  if (!same) {
    value_ = dynamics.mass_properties(masses, water_density);
    masses_ = masses;
    water_density_ = water_density;
    valid_ = true;
  }
  return value_;
}

std::array<GliderDynamics::PointMass, 4> GliderDynamics::point_masses(const MassInputs& masses,
                                                                      double water_density) const {
  const VehicleParams& v = vehicle_;
  // Pumping water out (positive volume) is modelled, as in Leonard-Graver, as
  // a negative point mass at the engine: same force and moment as the volume.
  const double ballast_kg = -water_density * masses.pumped_volume_m3;
  return {{
      {v.offset.mass_kg, v.offset.x_m, v.offset.z_m},
      {ballast_kg, v.ballast.x_m, v.ballast.z_m},
      {v.battery.mass_kg, v.battery.x_at_zero_m + masses.battery_pos_m, v.battery.z_m},
      {v.second_mass.mass_kg, v.second_mass.x_at_zero_m + masses.second_pos_m, v.second_mass.z_m},
  }};
}

GliderDynamics::MassProperties GliderDynamics::mass_properties(const MassInputs& masses, double water_density) const {
  const VehicleParams& v = vehicle_;
  MassProperties p;
  const RigidMasses rigid = rigid_masses(masses, water_density);
  p.total_kg = rigid.total_kg;
  p.first_x = rigid.first_x;
  p.first_z = rigid.first_z;
  double inertia = v.hull_inertia_kg_m2 + v.added_inertia_kg_m2;
  for (const PointMass& point : point_masses(masses, water_density)) {
    inertia += point.m * (point.x * point.x + point.z * point.z);
  }
  // T = 1/2 xi^T A xi + xi^T b + ..., xi = (v1, v3, q). For a point mass at
  // r = (x, z): its velocity is v + Omega x r + rdot, Omega x r = (q z, -q x).
  p.a << p.total_kg + v.added_mass_x_kg, 0.0, p.first_z,  //
      0.0, p.total_kg + v.added_mass_z_kg, -p.first_x,    //
      p.first_z, -p.first_x, inertia;
  // The moving masses slide along x: rdot = (rate, 0); angular part z * rate.
  const double m1 = v.battery.mass_kg * masses.battery_rate_m_s;
  const double m2 = v.second_mass.mass_kg * masses.second_rate_m_s;
  p.b << m1 + m2, 0.0, m1 * v.battery.z_m + m2 * v.second_mass.z_m;
  // A is symmetric positive definite and 3x3: the closed-form inverse is
  // exact enough (condition ~1e3) and several times faster than a factorisation.
  p.a_inverse = p.a.inverse();
  return p;
}

double GliderDynamics::immersed_fraction(double z_m) const {
  const double r = 0.5 * vehicle_.hull_diameter_m;
  if (z_m >= r) return 1.0;
  if (z_m <= -r) return 0.0;
  const double u = (z_m + r) / (2.0 * r);
  return u * u * (3.0 - 2.0 * u);
}

double GliderDynamics::displaced_volume_m3(double z_m, const WaterSample& water) const {
  const VehicleParams& v = vehicle_;
  const double gauge_pa = water.density_kg_m3 * environment_.gravity_m_s2 * std::max(z_m, 0.0);
  const double scale = 1.0 - v.hull_compressibility_per_pa * gauge_pa +
                       v.hull_thermal_expansion_per_k * (water.temperature_c - v.hull_reference_temperature_c);
  return nominal_volume_m3_ * scale * immersed_fraction(z_m);
}

double GliderDynamics::net_buoyancy_kg(double z_m, const WaterSample& water, const MassInputs& masses) const {
  return mass_properties(masses, water.density_kg_m3).total_kg - water.density_kg_m3 * displaced_volume_m3(z_m, water);
}

Evaluation GliderDynamics::evaluate(double time_s, const State& s, const MassInputs& masses, MassCache* cache) const {
  Evaluation e;
  e.water = environment_.water.at(s[kZ], time_s);
  const double rho = e.water.density_kg_m3;
  MassProperties computed;
  const MassProperties& mp = cache ? cache->get(*this, masses, rho) : (computed = mass_properties(masses, rho));
  const Eigen::Vector3d impulse(s[kP1], s[kP3], s[kPi2]);
  const Eigen::Vector3d xi = mp.a_inverse * (impulse - mp.b);
  e.v1 = xi[0];
  e.v3 = xi[1];
  e.q = xi[2];
  const double theta = s[kTheta];
  const double sin_t = std::sin(theta);
  const double cos_t = std::cos(theta);
  const double g = environment_.gravity_m_s2;

  // Weight and buoyancy (buoyancy acts at the CB: no moment).
  e.displaced_volume_m3 = displaced_volume_m3(s[kZ], e.water);
  e.net_buoyancy_kg = mp.total_kg - rho * e.displaced_volume_m3;  // as net_buoyancy_kg(), sharing mass_properties
  double f1 = -e.net_buoyancy_kg * g * sin_t;
  double f3 = e.net_buoyancy_kg * g * cos_t;
  e.gravity_moment_nm = -g * (mp.first_x * cos_t + mp.first_z * sin_t);

  // Lift, drag and viscous moment from the flow relative to the water.
  const Hydrodynamics& h = vehicle_.hydro;
  const FlowForces flow = flow_forces(h, rho, e.v1, e.v3);
  e.speed_m_s = flow.speed_m_s;
  e.alpha_rad = flow.alpha_rad;
  e.lift_n = flow.lift_n;
  e.drag_n = flow.drag_n;
  f1 += flow.f1;
  f3 += flow.f3;
  e.hydro_moment_nm = flow.moment_nm;
  const double lift_coefficient = flow.lift_coefficient;
  const double half_rho_a = 0.5 * rho * h.reference_area_m2;
  e.hydro_moment_nm += half_rho_a * e.speed_m_s * h.cmq_m2 * e.q;

  // Kirchhoff: the rotating frame's terms. v x P about y is v3 P1 - v1 P3.
  e.munk_moment_nm = -(e.v3 * impulse[0] - e.v1 * impulse[1]);

  // Heading (see the header): yaw rate relaxes toward what fin and roll ask.
  const HeadingModel& hd = vehicle_.heading;
  const double slope = lift_slope_per_rad(h);
  const double alpha_effective = slope != 0.0 ? lift_coefficient / slope : 0.0;
  const double yaw_rate_target = e.speed_m_s * (hd.fin_yaw_gain_per_m * masses.fin_rad +
                                                hd.roll_yaw_gain_per_m * alpha_effective * sin_roll_offset_) +
                                 masses.yaw_disturbance_rad_s;

  e.horizontal_speed_m_s = e.v1 * cos_t + e.v3 * sin_t;
  const double psi = s[kPsi];
  State& d = e.state_dot;
  d[kEast] = e.horizontal_speed_m_s * std::sin(psi) + e.water.current_east_m_s;
  d[kNorth] = e.horizontal_speed_m_s * std::cos(psi) + e.water.current_north_m_s;
  d[kZ] = -e.v1 * sin_t + e.v3 * cos_t + e.water.vertical_velocity_m_s;
  d[kTheta] = e.q;
  d[kP1] = f1 - e.q * impulse[1];
  d[kP3] = f3 + e.q * impulse[0];
  d[kPi2] = e.gravity_moment_nm + e.hydro_moment_nm + e.munk_moment_nm;
  // A rolled glider that pitches swings its nose sideways: Euler's
  // kinematics, heading rate = theta_dot tan(roll) / cos(theta) + the turn
  // (the inflections of a glider rolled 10 deg turn it ~9 deg each; the comet
  // 2019 logs show it, docs/heading-control.md).
  d[kPsi] = s[kYawRate] + e.q * tan_roll_offset_ / cos_t;
  // Crossing a vertical shear of the current turns it (shear_turn_per_unit).
  // (Only in sheared water: the vertical plane's fits evaluate this often.)
  if (e.water.current_shear_east_per_s != 0.0 || e.water.current_shear_north_per_s != 0.0) {
    const double cross_shear =
        e.water.current_shear_east_per_s * std::cos(psi) - e.water.current_shear_north_per_s * std::sin(psi);
    d[kPsi] += shear_turn_per_unit(d[kZ], e.speed_m_s) * cross_shear;
  }
  d[kYawRate] = (yaw_rate_target - s[kYawRate]) / hd.yaw_time_constant_s;
  return e;
}

State GliderDynamics::make_state(double z_m, double theta_rad, double v1, double v3, double q,
                                 const MassInputs& masses) const {
  const MassProperties mp = mass_properties(masses, environment_.water.at(z_m, 0.0).density_kg_m3);
  const Eigen::Vector3d impulse = mp.a * Eigen::Vector3d(v1, v3, q) + mp.b;
  State s = State::Zero();
  s[kZ] = z_m;
  s[kTheta] = theta_rad;
  s[kP1] = impulse[0];
  s[kP3] = impulse[1];
  s[kPi2] = impulse[2];
  return s;
}

double GliderDynamics::static_pitch_rad(const MassInputs& masses) const {
  // Zero moment of the weights about the CB: sum m (x cos t + z sin t) = 0.
  const MassProperties mp = mass_properties(masses, environment_.water.at(0.0, 0.0).density_kg_m3);
  return std::atan2(-mp.first_x, mp.first_z);
}

}  // namespace glider::model
