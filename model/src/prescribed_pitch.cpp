// SPDX-License-Identifier: Apache-2.0
#include "glider/model/prescribed_pitch.hpp"

#include <cmath>
#include <cstring>

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

// The translational block of the generalized mass matrix (dynamics.hpp's A):
// diagonal, coupled to q by its third column.
struct TranslationalMass {
  double a11, a33, a13, a23;  // A(0,0), A(1,1), A(0,2), A(1,2)
};

TranslationalMass translational(const VehicleParams& v, const GliderDynamics::RigidMasses& m) {
  return {m.total_kg + v.added_mass_x_kg, m.total_kg + v.added_mass_z_kg, m.first_z, -m.first_x};
}

// Body velocities from the impulses with the pitch rate prescribed.
Eigen::Vector2d velocities_from(const TranslationalMass& a, const Eigen::Vector2d& p, double q) {
  return {(p[0] - a.a13 * q) / a.a11, (p[1] - a.a23 * q) / a.a33};
}

}  // namespace

PrescribedPitchDynamics::PrescribedPitchDynamics(const VehicleParams& vehicle, double gravity_m_s2)
    : dynamics_(vehicle, Environment{WaterColumn(vehicle.trim_density_kg_m3), gravity_m_s2}) {}

Eigen::Vector2d PrescribedPitchDynamics::velocities(const Impulse& p, const PrescribedPitchInputs& in) const {
  const auto m = dynamics_.rigid_masses(masses_of(in), in.density_kg_m3);
  return velocities_from(translational(dynamics_.vehicle(), m), p, in.q_rad_s);
}

PrescribedPitchDynamics::Impulse PrescribedPitchDynamics::impulse(double v1, double v3,
                                                                  const PrescribedPitchInputs& in) const {
  const auto a = translational(dynamics_.vehicle(), dynamics_.rigid_masses(masses_of(in), in.density_kg_m3));
  return {a.a11 * v1 + a.a13 * in.q_rad_s, a.a33 * v3 + a.a23 * in.q_rad_s};
}

double PrescribedPitchDynamics::net_buoyancy_kg(const PrescribedPitchInputs& in) const {
  return dynamics_.net_buoyancy_kg(in.depth_m, water_of(in), masses_of(in));
}

PrescribedPitchDynamics::Stage PrescribedPitchDynamics::stage(const PrescribedPitchInputs& in) const {
  const WaterSample water = water_of(in);
  const auto m = dynamics_.rigid_masses(masses_of(in), in.density_kg_m3);
  const TranslationalMass a = translational(dynamics_.vehicle(), m);
  return {in,
          a.a11,
          a.a33,
          a.a13,
          a.a23,
          m.total_kg - in.density_kg_m3 * dynamics_.displaced_volume_m3(in.depth_m, water),
          std::sin(in.theta_rad),
          std::cos(in.theta_rad)};
}

Eigen::Vector2d PrescribedPitchDynamics::velocities(const Impulse& p, const Stage& s) const {
  return velocities_from({s.a11, s.a33, s.a13, s.a23}, p, s.in.q_rad_s);
}

PrescribedPitchDynamics::Derivative PrescribedPitchDynamics::derivative(const Impulse& p, const Stage& s) const {
  const Eigen::Vector2d v = velocities_from({s.a11, s.a33, s.a13, s.a23}, p, s.in.q_rad_s);
  const FlowForces flow = flow_forces_at_speed(dynamics_.vehicle().hydro, s.in.density_kg_m3, v[0], v[1],
                                               std::sqrt(v[0] * v[0] + v[1] * v[1]), false);
  const double g = dynamics_.environment().gravity_m_s2;
  const double f1 = -s.net_kg * g * s.sin_theta + flow.f1;
  const double f3 = s.net_kg * g * s.cos_theta + flow.f3;
  return {{f1 - s.in.q_rad_s * p[1], f3 + s.in.q_rad_s * p[0]}, -v[0] * s.sin_theta + v[1] * s.cos_theta};
}

PrescribedPitchDynamics::Derivative PrescribedPitchDynamics::derivative(const Impulse& p,
                                                                        const PrescribedPitchInputs& in) const {
  // Bitwise the same inputs (NaN included): the same stage.
  static_assert(sizeof(PrescribedPitchInputs) == 7 * sizeof(double), "compared as bytes: no padding");
  if (!stage_valid_ || std::memcmp(&in, &stage_.in, sizeof in) != 0) {
    stage_ = stage(in);
    stage_valid_ = true;
  }
  return derivative(p, stage_);
}

PrescribedPitchDynamics::Impulse PrescribedPitchDynamics::rate(const Impulse& p,
                                                               const PrescribedPitchInputs& in) const {
  return derivative(p, in).p_dot;
}

double PrescribedPitchDynamics::depth_rate_m_s(const Impulse& p, const PrescribedPitchInputs& in) const {
  const Eigen::Vector2d v = velocities(p, in);
  return -v[0] * std::sin(in.theta_rad) + v[1] * std::cos(in.theta_rad);
}

}  // namespace glider::model
