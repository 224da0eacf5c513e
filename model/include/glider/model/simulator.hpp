// SPDX-License-Identifier: Apache-2.0
#pragma once
#include <array>
#include <optional>

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

// The plant for SIL: vehicle dynamics plus its servos, advanced with the
// classic Runge-Kutta 4 (Boost.Odeint) in steps of kDefaultStepS (submerged)
// or kSurfaceStepS (near the surface), each ending at a servo's stop or a fin
// command's dead time if one falls inside it.
class GliderSimulator {
 public:
  // Integration step (classic RK4) while submerged. tests/unit/
  // test_dynamics.cpp checks the linearized model's eigenvalues against it
  // (the fastest submerged mode, heave / angle of attack, is ~1 s^-1: RK4 is
  // stable to |lambda h| = 2.8) and tests/unit/test_integration_accuracy.cpp
  // checks glides, turns and surfacing against a run at 0.01 s.
  static constexpr double kDefaultStepS = 1.0;
  // At the surface the waterplane (the buoyancy of a partly immersed hull
  // changes over one hull diameter) adds an undamped heave oscillation
  // (2.4 rad/s for a Slocum): within a hull diameter plus this margin of the
  // surface the step is at most kSurfaceStepS. The margin is more than a
  // glider travels vertically in one submerged step.
  static constexpr double kSurfaceStepS = 0.1;
  static constexpr double kSurfaceZoneMarginM = 1.5;

  // `step_s` is cut to what the vehicle's fastest mode allows (stable_step.hpp).
  GliderSimulator(const VehicleParams& vehicle, const Environment& environment, double step_s = kDefaultStepS);

  // Floating at rest at the surface, servos at the given positions.
  void reset_at_surface(double pumped_volume_m3, double battery_pos_m, double heading_rad = 0.0);
  // At rest at depth (pitch at its static value).
  void reset_at_depth(double depth_m, double pumped_volume_m3, double battery_pos_m, double heading_rad = 0.0);

  void command_pumped_volume_m3(double volume) { retarget(pump_, volume); }
  void command_battery_pos_m(double position) { retarget(battery_, position); }
  void command_second_pos_m(double position) { retarget(second_, position); }
  // The fin starts toward a command heading.fin_delay_s after it is given
  // (an integration step ends there): the servo's dead time.
  void command_fin_rad(double angle);
  // Held from now on (the SIL's draw of heading.yaw_disturbance_rad_s).
  void set_yaw_disturbance_rad_s(double rate) { yaw_disturbance_rad_s_ = rate; }

  // Advance by `duration_s` (a whole number of integration steps; the last
  // one is shortened if needed).
  void advance(double duration_s);

  Truth truth() const;
  // The dynamics evaluated at the current state and servo commands; computed
  // once and kept until the state or a command changes (the log, GPS, power
  // model and the next integration step all ask for it).
  const Evaluation& current() const;
  double time_s() const { return time_s_; }
  double step_s() const { return step_s_; }  // the submerged step in use
  const State& state() const { return state_; }
  const GliderDynamics& dynamics() const { return dynamics_; }
  const RateLimitedServo& pump() const { return pump_; }
  const RateLimitedServo& battery() const { return battery_; }
  const RateLimitedServo& second_mass() const { return second_; }
  const RateLimitedServo& fin() const { return fin_; }

 private:
  void step(double h);
  void apply_due_fin_commands();
  // Sets a servo's target; current() is recomputed only if the target moved
  // (the firmware repeats most commands every cycle).
  void retarget(RateLimitedServo& servo, double target);
  // The fin's retarget, through the servo's position deadband.
  void retarget_fin(double angle);
  // The step shortened to end at an event `event_s` ahead, if it falls inside it.
  static double step_until(double event_s, double h);
  static constexpr double kMinEventStepS = 1e-6;
  void reset_servos(double pumped_volume_m3, double battery_pos_m);
  MassInputs masses_after(double t) const;
  double displaced_pump_volume_after(double t) const;

  GliderDynamics dynamics_;
  double step_s_;
  double surface_zone_m_;  // depth above which the step is at most kSurfaceStepS
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
  mutable GliderDynamics::MassCache mass_cache_;
  mutable std::optional<Evaluation> current_;  // current(): empty when stale
};

}  // namespace glider::model
