// SPDX-License-Identifier: Apache-2.0
#include "glider/identification/pitch_trim.hpp"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <optional>

#include "glider/identification/least_squares.hpp"
#include "propagation.hpp"

namespace glider::identification {
namespace {

// Any depth well below the surface: the moments of a fully immersed hull do
// not depend on it (only the net buoyancy would, through compressibility).
constexpr double kEvaluationDepthM = 100.0;

model::MassInputs masses_of(const model::GliderDynamics& dynamics, const SteadyGlideSample& s) {
  // The ballast is a point mass m_b = -rho V at the engine: pumped volume from
  // the net buoyancy the pump gives, in the dynamics' own water.
  const double rho = dynamics.environment().water.at(kEvaluationDepthM, 0.0).density_kg_m3;
  model::MassInputs m;
  m.pumped_volume_m3 = -s.ballast_net_kg / rho;
  m.battery_pos_m = s.battery_pos_m;
  m.second_pos_m = s.second_pos_m;
  return m;
}

model::Evaluation steady_state(const model::GliderDynamics& dynamics, const SteadyGlideSample& s,
                               const GlideFromLift& g, const model::MassInputs& masses) {
  const model::State state = dynamics.make_state(kEvaluationDepthM, s.pitch_rad, g.speed_m_s * std::cos(g.alpha_rad),
                                                 g.speed_m_s * std::sin(g.alpha_rad), 0.0, masses);
  return dynamics.evaluate(0.0, state, masses);
}

}  // namespace

std::optional<GlideMoment> glide_moment(const model::GliderDynamics& dynamics, const LiftModel& lift,
                                        const SteadyGlideSample& sample, double buoyancy_offset_kg) {
  const auto glide = glide_from_lift(lift, sample, buoyancy_offset_kg);
  if (!glide) return std::nullopt;
  model::MassInputs masses = masses_of(dynamics, sample);
  const model::Evaluation e = steady_state(dynamics, sample, *glide, masses);
  const double dynamic_force_n =
      0.5 * lift.density_kg_m3 * lift.hydro.reference_area_m2 * glide->speed_m_s * glide->speed_m_s;
  GlideMoment m;
  m.glide = *glide;
  m.gravity_moment_nm = e.gravity_moment_nm;
  m.munk_moment_nm = e.munk_moment_nm;
  m.cm_total_m = -e.gravity_moment_nm / dynamic_force_n;
  m.cm_viscous_m = m.cm_total_m - e.munk_moment_nm / dynamic_force_n;
  // The gravity moment is affine in the battery position: one more
  // evaluation gives its slope exactly.
  const double probe_m = 0.01;
  masses.battery_pos_m += probe_m;
  const model::Evaluation moved = steady_state(dynamics, sample, *glide, masses);
  m.cm_per_battery_m_per_m = -(moved.gravity_moment_nm - e.gravity_moment_nm) / (dynamic_force_n * probe_m);
  return m;
}

namespace {

// The fit itself, without the input propagation.
PitchTrimEstimate fit_pitch_trim(const model::GliderDynamics& dynamics, const LiftModel& lift,
                                 std::span<const SteadyGlideSample> samples, double buoyancy_offset_kg) {
  PitchTrimEstimate est;
  int dives = 0;
  int climbs = 0;
  for (const SteadyGlideSample& s : samples) {
    const auto m = glide_moment(dynamics, lift, s, buoyancy_offset_kg);
    if (!m) {
      est.error = "a glide cannot be read through the lift equation with this buoyancy offset";
      return est;
    }
    est.glides.push_back(*m);
    (s.depth_rate_m_s > 0.0 ? dives : climbs) += 1;
  }
  if (dives == 0 || climbs == 0) {
    est.error = "needs steady glides both down and up: with one direction the pitch trim and cm_alpha are confounded";
    return est;
  }
  const auto n = static_cast<Eigen::Index>(est.glides.size());
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd total(n);
  Eigen::VectorXd viscous(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const GlideMoment& m = est.glides[static_cast<std::size_t>(i)];
    design(i, 0) = m.glide.alpha_rad;
    design(i, 1) = -m.cm_per_battery_m_per_m;
    total(i) = m.cm_total_m;
    viscous(i) = m.cm_viscous_m;
  }
  const LinearFit fit_total = least_squares(design, total);
  const LinearFit fit_viscous = least_squares(design, viscous);
  if (!fit_total.ok || !fit_viscous.ok) {
    est.error = "the moment fit is singular (need glides at different angles of attack)";
    return est;
  }
  est.ok = true;
  est.cm_alpha_total_m = fit_total.coefficients[0];
  est.cm_alpha_total_se_m = fit_total.standard_errors[0];
  est.pitch_trim_offset_m = fit_total.coefficients[1];
  est.pitch_trim_offset_se_m = fit_total.standard_errors[1];
  // The viscous fit finds the same trim up to the Munk moment's small
  // departure from linearity (sin a cos a); only its slope is reported.
  est.cm_alpha_viscous_m = fit_viscous.coefficients[0];
  est.cm_alpha_viscous_se_m = fit_viscous.standard_errors[0];
  est.residual_sd_m = fit_total.residual_sd;
  est.dof = fit_total.dof;
  const model::VehicleParams& v = dynamics.vehicle();
  est.offset_mass_x_m = v.offset.mass_kg > 0.0
                            ? v.offset.x_m + est.pitch_trim_offset_m * v.battery.mass_kg / v.offset.mass_kg
                            : std::numeric_limits<double>::quiet_NaN();
  return est;
}

}  // namespace

PitchTrimEstimate estimate_pitch_trim(const model::VehicleParams& vehicle, const LiftModel& lift,
                                      std::span<const SteadyGlideSample> samples, double buoyancy_offset_kg,
                                      const PitchTrimOptions& options) {
  model::Environment water = model::still_water(lift.density_kg_m3);
  water.gravity_m_s2 = lift.gravity_m_s2;
  const model::GliderDynamics dynamics(vehicle, water);
  PitchTrimEstimate est = fit_pitch_trim(dynamics, lift, samples, buoyancy_offset_kg);
  if (!est.ok) return est;

  auto estimate = [&](std::span<const SteadyGlideSample> perturbed,
                      double offset_kg) -> std::optional<Eigen::VectorXd> {
    const PitchTrimEstimate e = fit_pitch_trim(dynamics, lift, perturbed, offset_kg);
    if (!e.ok) return std::nullopt;
    return Eigen::Vector3d(e.pitch_trim_offset_m, e.cm_alpha_total_m, e.cm_alpha_viscous_m);
  };
  Eigen::VectorXd se = detail::propagate_sample_errors(
      samples, options.input_sd, 3,
      [&](std::span<const SteadyGlideSample> perturbed) { return estimate(perturbed, buoyancy_offset_kg); });
  if (options.buoyancy_offset_sd_kg > 0.0) {
    const auto plus = estimate(samples, buoyancy_offset_kg + options.buoyancy_offset_sd_kg);
    const auto minus = estimate(samples, buoyancy_offset_kg - options.buoyancy_offset_sd_kg);
    se = (plus && minus) ? (se.cwiseAbs2() + (0.5 * (*plus - *minus)).cwiseAbs2()).cwiseSqrt().eval()
                         : Eigen::VectorXd::Constant(3, std::numeric_limits<double>::quiet_NaN());
  }
  est.pitch_trim_offset_input_se_m = se[0];
  est.cm_alpha_total_input_se_m = se[1];
  est.cm_alpha_viscous_input_se_m = se[2];
  return est;
}

}  // namespace glider::identification
