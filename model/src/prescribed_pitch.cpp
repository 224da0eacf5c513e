// SPDX-License-Identifier: Apache-2.0
#include "glider/model/prescribed_pitch.hpp"

#include <cmath>

#include "flow_forces_inline.hpp"

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
    : dynamics_(vehicle, Environment{WaterColumn(vehicle.trim_density_kg_m3), gravity_m_s2}),
      slopes_(polar_slopes(vehicle.hydro)),
      skin_friction_(vehicle.hydro) {}

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

PrescribedPitchDynamics::Derivative PrescribedPitchDynamics::derivative(const Impulse& p,
                                                                        const PrescribedPitchInputs& in) const {
  return derivative(p, in, skin_friction_);
}

PrescribedPitchDynamics::Derivative PrescribedPitchDynamics::derivative(const Impulse& p,
                                                                        const PrescribedPitchInputs& in,
                                                                        const SkinFrictionFactor& friction) const {
  const PrescribedPitchInputs& k = stage_.in;
  // NaN (a log without temperature) matches NaN: the stage computes the same from either.
  auto eq = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
  const bool same = stage_.valid && eq(in.theta_rad, k.theta_rad) && eq(in.q_rad_s, k.q_rad_s) &&
                    eq(in.pumped_volume_m3, k.pumped_volume_m3) && eq(in.battery_pos_m, k.battery_pos_m) &&
                    eq(in.depth_m, k.depth_m) && eq(in.density_kg_m3, k.density_kg_m3) &&
                    eq(in.temperature_c, k.temperature_c);
  if (!same) {
    const WaterSample water = water_of(in);
    const auto m = dynamics_.rigid_masses(masses_of(in), in.density_kg_m3);
    const TranslationalMass a = translational(dynamics_.vehicle(), m);
    stage_ = {true,
              in,
              a.a11,
              a.a33,
              a.a13,
              a.a23,
              m.total_kg - in.density_kg_m3 * dynamics_.displaced_volume_m3(in.depth_m, water)};
  }
  if (!std::isnan(in.sin_theta)) {
    pitch_ = {true, in.theta_rad, in.sin_theta, in.cos_theta};
  } else if (!(pitch_.valid && eq(in.theta_rad, pitch_.theta_rad))) {
    pitch_ = {true, in.theta_rad, std::sin(in.theta_rad), std::cos(in.theta_rad)};
  }
  const Eigen::Vector2d v = velocities_from({stage_.a11, stage_.a33, stage_.a13, stage_.a23}, p, in.q_rad_s);
  const double net_kg = stage_.net_kg;
  const double speed = std::sqrt(v[0] * v[0] + v[1] * v[1]);
  const FlowForces flow =
      detail::flow_forces_at_angle(dynamics_.vehicle().hydro, slopes_, in.density_kg_m3, v[0], v[1], speed,
                                   detail::small_angle_atan2(v[1], v[0]), false, friction(speed));
  const double g = dynamics_.environment().gravity_m_s2;
  const double sin_theta = pitch_.sin_theta, cos_theta = pitch_.cos_theta;
  const double f1 = -net_kg * g * sin_theta + flow.f1;
  const double f3 = net_kg * g * cos_theta + flow.f3;
  return {{f1 - in.q_rad_s * p[1], f3 + in.q_rad_s * p[0]}, -v[0] * sin_theta + v[1] * cos_theta};
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
