// SPDX-License-Identifier: Apache-2.0
#pragma once
// The longest classic-RK4 step a vehicle's dynamics allow. RK4 is stable to
// |lambda h| ~ 2.8; a small, stiff vehicle (the IIT Madras lab glider: a
// 1.1 kg m^2 hull with a Slocum-sized pitch damping) has submerged modes
// fast enough that the default 1 s step diverges to NaN within a dive. The
// modes come from the linearized steady glides at the pump's limits (the
// fastest: hydrodynamic rates grow with speed), and the step is cut to keep
// |lambda| h <= kMaxLambdaStep, the margin tests/unit/test_dynamics.cpp keeps.
#include <Eigen/Core>
#include <array>

#include "glider/model/dynamics.hpp"

namespace glider::model {

inline constexpr double kMaxLambdaStep = 1.5;

// The states the dynamics depend on (position and heading feed nothing).
inline constexpr std::array<int, 6> kDynamicStates{kZ, kTheta, kP1, kP3, kPi2, kYawRate};

// Jacobian of the state derivative (central differences) over kDynamicStates.
Eigen::Matrix<double, 6, 6> dynamics_jacobian(const GliderDynamics& dyn, const State& s, const MassInputs& m);

// Fastest |lambda| (1/s) of the linearized steady glides at the pump's
// limits (battery at its zero, or at its travel's ends where that holds no
// glide; 100 m down); 0 if the vehicle has no glide there.
double fastest_glide_mode_per_s(const GliderDynamics& dynamics);

// `requested_s`, or less so that fastest_glide_mode_per_s() x step <= kMaxLambdaStep.
double stable_step_s(const GliderDynamics& dynamics, double requested_s);

}  // namespace glider::model
