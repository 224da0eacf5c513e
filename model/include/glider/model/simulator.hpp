// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>

#include "glider/model/dynamics.hpp"
#include "glider/model/servo.hpp"

namespace glider::model {

// What the simulation knows that a real glider does not (the sim_ columns).
struct Truth {
  double time_s = 0.0;
  double east_m = 0.0;  // position relative to the start
  double north_m = 0.0;
  double depth_m = 0.0;
  double heading_rad = 0.0;  // wrapped to [0, 2 pi)
  double yaw_rate_rad_s = 0.0;
  double pitch_rad = 0.0;
  double pitch_rate_rad_s = 0.0;
  double speed_m_s = 0.0;  // through the water
  double alpha_rad = 0.0;
  double glide_path_rad = 0.0;        // pitch - alpha
  double horizontal_speed_m_s = 0.0;  // through the water, along the heading
  double depth_rate_m_s = 0.0;        // + descending, over ground (includes water w)
  double net_buoyancy_kg = 0.0;
  double pumped_volume_m3 = 0.0;
  double battery_pos_m = 0.0;
  double fin_rad = 0.0;
  WaterSample water;
};

// The plant for SIL: vehicle dynamics plus its two servos, advanced with a
// fixed-step classic Runge-Kutta 4 (Boost.Odeint).
class GliderSimulator {
 public:
  // Integration step. The fastest mode of the SLOCUM model is the heave/
  // angle-of-attack mode (lift slope / heave mass ~ 1 s^-1; ~2 s^-1 when
  // bobbing at the surface), the pitch pendulum is ~0.4 rad/s: 0.1 s keeps
  // |lambda h| <= 0.3, where RK4's error per step is ~1e-5 relative and far
  // inside its stability limit (2.8). tests/unit/test_dynamics.cpp checks the
  // eigenvalues of the linearized model against this.
  static constexpr double kDefaultStepS = 0.1;

  GliderSimulator(const VehicleParams& vehicle, const Environment& environment, double step_s = kDefaultStepS);

  // Floating at rest at the surface, servos at the given positions.
  void reset_at_surface(double pumped_volume_m3, double battery_pos_m, double heading_rad = 0.0);
  // At rest at depth (pitch at its static value).
  void reset_at_depth(double depth_m, double pumped_volume_m3, double battery_pos_m, double heading_rad = 0.0);

  void command_pumped_volume_m3(double volume) { pump_.set_target(volume); }
  void command_battery_pos_m(double position) { battery_.set_target(position); }
  void command_second_pos_m(double position) { second_.set_target(position); }
  // The fin starts toward a command heading.fin_delay_s after it is given
  // (to the integration step): the servo's dead time.
  void command_fin_rad(double angle);
  // Held from now on (the SIL's draw of heading.yaw_disturbance_rad_s).
  void set_yaw_disturbance_rad_s(double rate) { yaw_disturbance_rad_s_ = rate; }

  // Advance by `duration_s` (a whole number of integration steps; the last
  // one is shortened if needed).
  void advance(double duration_s);

  Truth truth() const;
  double time_s() const { return time_s_; }
  const State& state() const { return state_; }
  const GliderDynamics& dynamics() const { return dynamics_; }
  const RateLimitedServo& pump() const { return pump_; }
  const RateLimitedServo& battery() const { return battery_; }
  const RateLimitedServo& second_mass() const { return second_; }
  const RateLimitedServo& fin() const { return fin_; }

 private:
  void step(double h);
  void reset_servos(double pumped_volume_m3, double battery_pos_m);
  MassInputs masses_after(double t) const;
  double displaced_pump_volume_after(double t) const;

  GliderDynamics dynamics_;
  double step_s_;
  RateLimitedServo pump_;
  RateLimitedServo battery_;
  RateLimitedServo second_;
  RateLimitedServo fin_;
  // Fin commands waiting out the dead time (time due, angle), a ring.
  struct PendingFin {
    double due_s;
    double angle_rad;
  };
  static constexpr std::size_t kMaxPendingFin = 64;
  std::array<PendingFin, kMaxPendingFin> pending_fin_{};
  std::size_t pending_first_ = 0;
  std::size_t pending_count_ = 0;
  double yaw_disturbance_rad_s_ = 0.0;
  double displaced_pump_volume_m3_ = 0.0;  // lags pump_ by ballast.lag_s (0: equal)
  State state_ = State::Zero();
  double time_s_ = 0.0;
};

}  // namespace glider::model
