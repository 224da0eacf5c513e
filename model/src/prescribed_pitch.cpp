// SPDX-License-Identifier: Apache-2.0
#include "glider/model/prescribed_pitch.hpp"

#include <cmath>

namespace glider::model {
namespace {

MassInputs masses_of(const PrescribedPitchInputs& in) {
  MassInputs m;
  m.pumped_volume_m3 = in.pumped_volume_m3;
  m.battery_pos_m = in.battery_pos_m;
  return m;
}

WaterSample water_of(const PrescribedPitchInputs& in) {
  WaterSample w;
  w.density_kg_m3 = in.density_kg_m3;
  w.temperature_c = in.temperature_c;
  return w;
}

// Body velocities from the impulses with the pitch rate prescribed: A's 2x2
// translational block is diagonal, its coupling to q is the third column.
Eigen::Vector2d velocities_from(const GliderDynamics::MassProperties& mp, const Eigen::Vector2d& p, double q) {
  return {(p[0] - mp.a(0, 2) * q) / mp.a(0, 0), (p[1] - mp.a(1, 2) * q) / mp.a(1, 1)};
}

}  // namespace

PrescribedPitchDynamics::PrescribedPitchDynamics(const VehicleParams& vehicle, double gravity_m_s2)
    : dynamics_(vehicle, Environment{WaterColumn(vehicle.trim_density_kg_m3), gravity_m_s2}) {}

Eigen::Vector2d PrescribedPitchDynamics::velocities(const Impulse& p, const PrescribedPitchInputs& in) const {
  return velocities_from(dynamics_.mass_properties(masses_of(in), in.density_kg_m3), p, in.q_rad_s);
}

PrescribedPitchDynamics::Impulse PrescribedPitchDynamics::impulse(double v1, double v3,
                                                                  const PrescribedPitchInputs& in) const {
  const auto mp = dynamics_.mass_properties(masses_of(in), in.density_kg_m3);
  return {mp.a(0, 0) * v1 + mp.a(0, 2) * in.q_rad_s, mp.a(1, 1) * v3 + mp.a(1, 2) * in.q_rad_s};
}

double PrescribedPitchDynamics::net_buoyancy_kg(const PrescribedPitchInputs& in) const {
  return dynamics_.net_buoyancy_kg(in.depth_m, water_of(in), masses_of(in));
}

PrescribedPitchDynamics::Impulse PrescribedPitchDynamics::rate(const Impulse& p,
                                                               const PrescribedPitchInputs& in) const {
  const WaterSample water = water_of(in);
  const auto mp = dynamics_.mass_properties(masses_of(in), in.density_kg_m3);
  const Eigen::Vector2d v = velocities_from(mp, p, in.q_rad_s);
  const double net_kg = mp.total_kg - in.density_kg_m3 * dynamics_.displaced_volume_m3(in.depth_m, water);
  const FlowForces flow = flow_forces(dynamics_.vehicle().hydro, in.density_kg_m3, v[0], v[1]);
  const double g = dynamics_.environment().gravity_m_s2;
  const double f1 = -net_kg * g * std::sin(in.theta_rad) + flow.f1;
  const double f3 = net_kg * g * std::cos(in.theta_rad) + flow.f3;
  return {f1 - in.q_rad_s * p[1], f3 + in.q_rad_s * p[0]};
}

double PrescribedPitchDynamics::depth_rate_m_s(const Impulse& p, const PrescribedPitchInputs& in) const {
  const Eigen::Vector2d v = velocities(p, in);
  return -v[0] * std::sin(in.theta_rad) + v[1] * std::cos(in.theta_rad);
}

}  // namespace glider::model
