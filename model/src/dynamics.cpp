#include "glider/model/dynamics.hpp"

#include <cmath>
#include <Eigen/Dense>

#include "glider/model/hydrodynamics.hpp"

namespace glider::model {

GliderDynamics::GliderDynamics(const VehicleParams& vehicle, const Environment& environment)
    : vehicle_(vehicle), environment_(environment), displaced_volume_m3_(displaced_volume_m3(vehicle)) {}

GliderDynamics::MassProperties GliderDynamics::mass_properties(const MassInputs& masses) const {
  const VehicleParams& v = vehicle_;
  // Pumping water out (positive volume) is modelled, as in Leonard-Graver, as
  // a negative point mass at the engine: same force and moment as the volume.
  const double ballast_kg = -environment_.density_kg_m3 * masses.pumped_volume_m3;
  const double battery_x = v.battery.x_at_zero_m + masses.battery_pos_m;

  struct Point {
    double m, x, z;
  };
  const Point points[] = {
      {v.offset.mass_kg, v.offset.x_m, v.offset.z_m},
      {ballast_kg, v.ballast.x_m, v.ballast.z_m},
      {v.battery.mass_kg, battery_x, v.battery.z_m},
  };
  MassProperties p;
  p.total_kg = v.hull_mass_kg;
  double inertia = v.hull_inertia_kg_m2 + v.added_inertia_kg_m2;
  for (const Point& point : points) {
    p.total_kg += point.m;
    p.first_x += point.m * point.x;
    p.first_z += point.m * point.z;
    inertia += point.m * (point.x * point.x + point.z * point.z);
  }
  // T = 1/2 xi^T A xi + xi^T b + ..., xi = (v1, v3, q). For a point mass at
  // r = (x, z): its velocity is v + Omega x r + rdot, Omega x r = (q z, -q x).
  p.a << p.total_kg + v.added_mass_x_kg, 0.0, p.first_z,  //
      0.0, p.total_kg + v.added_mass_z_kg, -p.first_x,     //
      p.first_z, -p.first_x, inertia;
  const double m = v.battery.mass_kg;
  const double rate = masses.battery_rate_m_s;
  // Slide moves along x: rdot = (rate, 0); angular part r x rdot = z * rate.
  p.b << m * rate, 0.0, m * v.battery.z_m * rate;
  return p;
}

double GliderDynamics::immersed_fraction(double z_m) const {
  const double r = 0.5 * vehicle_.hull_diameter_m;
  if (z_m >= r) return 1.0;
  if (z_m <= -r) return 0.0;
  const double u = (z_m + r) / (2.0 * r);
  return u * u * (3.0 - 2.0 * u);
}

Evaluation GliderDynamics::evaluate(const State& s, const MassInputs& masses) const {
  const MassProperties mp = mass_properties(masses);
  const Eigen::Vector3d impulse(s[kP1], s[kP3], s[kPi2]);
  const Eigen::Vector3d xi = mp.a.ldlt().solve(impulse - mp.b);

  Evaluation e;
  e.v1 = xi[0];
  e.v3 = xi[1];
  e.q = xi[2];
  const double theta = s[kTheta];
  const double sin_t = std::sin(theta);
  const double cos_t = std::cos(theta);
  const double g = environment_.gravity_m_s2;
  const double rho = environment_.density_kg_m3;

  // Weight and buoyancy (buoyancy acts at the CB: no moment).
  const double displaced_kg = rho * displaced_volume_m3_ * immersed_fraction(s[kZ]);
  e.net_buoyancy_kg = mp.total_kg - displaced_kg;
  double f1 = -e.net_buoyancy_kg * g * sin_t;
  double f3 = e.net_buoyancy_kg * g * cos_t;
  e.gravity_moment_nm = -g * (mp.first_x * cos_t + mp.first_z * sin_t);

  // Lift, drag and viscous moment from the flow relative to the water.
  const Hydrodynamics& h = vehicle_.hydro;
  e.speed_m_s = std::hypot(e.v1, e.v3);
  e.alpha_rad = std::atan2(e.v3, e.v1);
  const double half_rho_a = 0.5 * rho * h.reference_area_m2;
  if (e.speed_m_s > 0.0) {
    const ForceCoefficients c = force_coefficients(h, e.alpha_rad);
    const double dyn = half_rho_a * e.speed_m_s * e.speed_m_s;
    e.lift_n = dyn * c.lift;
    e.drag_n = dyn * c.drag;
    const double cos_a = e.v1 / e.speed_m_s;
    const double sin_a = e.v3 / e.speed_m_s;
    f1 += e.lift_n * sin_a - e.drag_n * cos_a;
    f3 += -e.lift_n * cos_a - e.drag_n * sin_a;
    e.hydro_moment_nm = dyn * moment_coefficient(h, e.alpha_rad);
  }
  e.hydro_moment_nm += half_rho_a * e.speed_m_s * h.cmq_m2 * e.q;

  // Kirchhoff: the rotating frame's terms. v x P about y is v3 P1 - v1 P3.
  e.munk_moment_nm = -(e.v3 * impulse[0] - e.v1 * impulse[1]);

  State& d = e.state_dot;
  d[kX] = e.v1 * cos_t + e.v3 * sin_t + environment_.current_along_track_m_s;
  d[kZ] = -e.v1 * sin_t + e.v3 * cos_t + environment_.vertical_velocity_m_s;
  d[kTheta] = e.q;
  d[kP1] = f1 - e.q * impulse[1];
  d[kP3] = f3 + e.q * impulse[0];
  d[kPi2] = e.gravity_moment_nm + e.hydro_moment_nm + e.munk_moment_nm;
  return e;
}

State GliderDynamics::make_state(double x_m, double z_m, double theta_rad, double v1, double v3, double q,
                                 const MassInputs& masses) const {
  const MassProperties mp = mass_properties(masses);
  const Eigen::Vector3d impulse = mp.a * Eigen::Vector3d(v1, v3, q) + mp.b;
  State s;
  s << x_m, z_m, theta_rad, impulse[0], impulse[1], impulse[2];
  return s;
}

double GliderDynamics::static_pitch_rad(const MassInputs& masses) const {
  // Zero moment of the weights about the CB: sum m (x cos t + z sin t) = 0.
  const MassProperties mp = mass_properties(masses);
  return std::atan2(-mp.first_x, mp.first_z);
}

}  // namespace glider::model
