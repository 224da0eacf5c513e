// SPDX-License-Identifier: Apache-2.0
#pragma once
// The truth's equations of motion: a rigid body in the vertical plane in
// body axes (surge u, heave w, pitch rate q; origin at the centre of
// buoyancy, x forward, z down, pitch + nose up) with the centre of gravity
// offset by the fixed and battery masses (Fossen's rigid-body terms),
// diagonal added masses with their Coriolis and Munk terms, the
// hydrodynamics of vehicle.hpp with the lift lagged, and the water of
// water.hpp. The heading plane: a second-order yaw (two poles) driven by the
// fin (a dead time after the servo) and by the roll (the horizontal part of
// the lift), the roll lagging the fin's heel. Actuators are states that move
// at their rate limits toward their targets; the pump's displaced volume
// lags its reading (pump_lag); the pressure sensor lags the depth.
#include <array>
#include <cstddef>
#include <vector>

#include "glider/truth/vehicle.hpp"
#include "glider/truth/water.hpp"

namespace glider::truth {

enum StateIndex : std::size_t {
  kNorth,
  kEast,
  kDepth,
  kPitch,
  kSurge,
  kHeave,
  kPitchRate,
  kHeading,
  kYawRate,
  kYawAcceleration,
  kRoll,
  kLift,  // the lagged lift coefficient
  kPiston,
  kDisplaced,
  kBattery,
  kFin,
  kSensedDepth,
  kStateSize
};
using State = std::array<double, kStateSize>;

constexpr double kGravity = 9.81;

struct Targets {
  double piston_m3 = 0.0, battery_m = 0.0, fin_rad = 0.0;
  double yaw_disturbance_rad_s = 0.0;  // slow yaw forcing nothing in the log explains (AR(1), per cycle)
};

// The fin's past positions for the yaw's dead time (times increasing).
struct FinHistory {
  std::vector<double> time_s, fin_rad;
  void add(double t, double fin);
  double at(double t) const;  // linear between samples, held outside
};

struct Dynamics {
  const Vehicle& vehicle;
  const Water& water;
  Targets targets;
  double yaw_delay_s = 0.0, fin_effectiveness = 1.0, depth_sensor_lag_s = 0.3;
  const FinHistory* fin_history = nullptr;

  void operator()(double t, const State& y, State& dydt) const;

  // Diagnostics of a state (also what the log's sim_ truth columns show).
  struct Forces {
    double speed_m_s, alpha_rad, density_kg_m3, net_weight_n, lift_coefficient, drag_coefficient;
  };
  Forces forces(double t, const State& y) const;
};

// Kinetic energy of the body with its added masses (J), for the tests'
// energy balance: dE/dt = power of gravity-buoyancy + hydrodynamic power.
double kinetic_energy(const Vehicle& v, const State& y);

}  // namespace glider::truth
