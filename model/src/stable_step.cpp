// SPDX-License-Identifier: Apache-2.0
#include "glider/model/stable_step.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>

#include "glider/model/steady_glide.hpp"

namespace glider::model {

Eigen::Matrix<double, 6, 6> dynamics_jacobian(const GliderDynamics& dyn, const State& s, const MassInputs& m) {
  Eigen::Matrix<double, 6, 6> j;
  for (std::size_t col = 0; col < kDynamicStates.size(); ++col) {
    const int k = kDynamicStates[col];
    const double h = 1e-6 * std::max(1.0, std::abs(s[k]));
    State plus = s;
    State minus = s;
    plus[k] += h;
    minus[k] -= h;
    const State d = (dyn.derivative(0.0, plus, m) - dyn.derivative(0.0, minus, m)) / (2.0 * h);
    for (std::size_t row = 0; row < kDynamicStates.size(); ++row)
      j(static_cast<int>(row), static_cast<int>(col)) = d[kDynamicStates[row]];
  }
  return j;
}

double fastest_glide_mode_per_s(const GliderDynamics& dynamics) {
  const VehicleParams& v = dynamics.vehicle();
  constexpr double kDepthM = 100.0;  // well clear of the surface (its own step)
  double fastest = 0.0;
  for (const double pumped : {v.ballast.volume_min_m3, v.ballast.volume_max_m3}) {
    // The battery at its zero; where that holds no glide, its travel's ends.
    for (const double battery : {0.0, v.battery.travel_min_m, v.battery.travel_max_m}) {
      MassInputs m;
      m.pumped_volume_m3 = pumped;
      m.battery_pos_m = battery;
      const SteadyGlideResult steady = solve_equilibrium(dynamics, m, kDepthM);
      if (!steady.glide) continue;
      const SteadyGlide& g = *steady.glide;
      const State s = dynamics.make_state(kDepthM, g.pitch_rad, g.speed_m_s * std::cos(g.alpha_rad),
                                          g.speed_m_s * std::sin(g.alpha_rad), 0.0, m);
      const Eigen::EigenSolver<Eigen::Matrix<double, 6, 6>> solver(dynamics_jacobian(dynamics, s, m), false);
      if (solver.info() != Eigen::Success) continue;
      for (int i = 0; i < 6; ++i) {
        const double magnitude = std::abs(solver.eigenvalues()[i]);
        if (std::isfinite(magnitude)) fastest = std::max(fastest, magnitude);
      }
      break;
    }
  }
  return fastest;
}

double stable_step_s(const GliderDynamics& dynamics, double requested_s) {
  const double fastest = fastest_glide_mode_per_s(dynamics);
  return fastest > 0.0 ? std::min(requested_s, kMaxLambdaStep / fastest) : requested_s;
}

}  // namespace glider::model
