// SPDX-License-Identifier: Apache-2.0
#include "glider/model/simulator.hpp"

#include <boost/numeric/odeint/external/eigen/eigen_algebra.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <cmath>

#include <numbers>

#include "glider/model/first_order_lag.hpp"
#include "glider/model/root_finding.hpp"

namespace glider::model {
namespace {

using Stepper =
    boost::numeric::odeint::runge_kutta4<State, double, State, double, boost::numeric::odeint::vector_space_algebra>;

RateLimitedServo make_slide(const SlidingMass& m, double initial) {
  // An absent second mass still gets a (motionless) servo.
  if (!(m.travel_min_m < m.travel_max_m)) return RateLimitedServo(0.0, 0.0, 1.0, 0.0);
  return RateLimitedServo(m.travel_min_m, m.travel_max_m, m.rate_m_s, initial);
}

}  // namespace

GliderSimulator::GliderSimulator(const VehicleParams& vehicle, const Environment& environment, double step_s)
    : dynamics_(vehicle, environment),
      step_s_(step_s),
      pump_(vehicle.ballast.volume_min_m3, vehicle.ballast.volume_max_m3, vehicle.ballast.rate_m3_s, 0.0),
      battery_(make_slide(vehicle.battery, 0.0)),
      second_(make_slide(vehicle.second_mass, 0.0)),
      fin_(-vehicle.heading.fin_max_rad, vehicle.heading.fin_max_rad, vehicle.heading.fin_rate_rad_s, 0.0) {}

double GliderSimulator::displaced_pump_volume_after(double t) const {
  const double lag = dynamics_.vehicle().ballast.lag_s;
  if (!(lag > 0.0)) return pump_.position_after(t);
  // The servo's path over the step is close to linear (it can stop inside
  // one 0.1 s step at most once): lag its mean slope exactly.
  return first_order_lag_after(displaced_pump_volume_m3_, pump_.position(), pump_.position_after(t), t, lag);
}

MassInputs GliderSimulator::masses_after(double t) const {
  MassInputs m;
  m.pumped_volume_m3 = displaced_pump_volume_after(t);
  m.battery_pos_m = battery_.position_after(t);
  m.battery_rate_m_s = battery_.velocity_after(t);
  m.second_pos_m = second_.position_after(t);
  m.second_rate_m_s = second_.velocity_after(t);
  m.fin_rad = fin_.position_after(t);
  m.yaw_disturbance_rad_s = yaw_disturbance_rad_s_;
  return m;
}

void GliderSimulator::reset_servos(double pumped_volume_m3, double battery_pos_m) {
  const VehicleParams& v = dynamics_.vehicle();
  pump_ = RateLimitedServo(v.ballast.volume_min_m3, v.ballast.volume_max_m3, v.ballast.rate_m3_s, pumped_volume_m3);
  displaced_pump_volume_m3_ = pumped_volume_m3;
  battery_ = make_slide(v.battery, battery_pos_m);
  second_ = make_slide(v.second_mass, 0.0);
  fin_ = RateLimitedServo(-v.heading.fin_max_rad, v.heading.fin_max_rad, v.heading.fin_rate_rad_s, 0.0);
  pending_count_ = 0;
}

void GliderSimulator::reset_at_depth(double depth_m, double pumped_volume_m3, double battery_pos_m,
                                     double heading_rad) {
  reset_servos(pumped_volume_m3, battery_pos_m);
  const MassInputs m = masses_after(0.0);
  state_ = dynamics_.make_state(depth_m, dynamics_.static_pitch_rad(m), 0.0, 0.0, 0.0, m);
  state_[kPsi] = heading_rad;
  time_s_ = 0.0;
}

void GliderSimulator::reset_at_surface(double pumped_volume_m3, double battery_pos_m, double heading_rad) {
  reset_at_depth(0.0, pumped_volume_m3, battery_pos_m, heading_rad);
  // Float level: the depth where weight and (partial) buoyancy balance.
  const MassInputs m = masses_after(0.0);
  // Net buoyancy falls with depth there, from + (heavy, in the air) to - (submerged).
  auto net_buoyancy_at = [&](double z) {
    State probe = state_;
    probe[kZ] = z;
    return dynamics_.evaluate(0.0, probe, m).net_buoyancy_kg;
  };
  const double d = dynamics_.vehicle().hull_diameter_m;
  state_[kZ] = bracketed_root(net_buoyancy_at, -d, d);
}

void GliderSimulator::step(double h) {
  Stepper stepper;
  // The servos' paths over [t, t + h] are closed-form: evaluate them at each
  // RK4 stage time instead of holding them constant over the step.
  const double t0 = time_s_;
  auto rhs = [this, t0](const State& s, State& ds, double t) { ds = dynamics_.derivative(t, s, masses_after(t - t0)); };
  stepper.do_step(rhs, state_, t0, h);
  displaced_pump_volume_m3_ = displaced_pump_volume_after(h);
  pump_.advance(h);
  battery_.advance(h);
  second_.advance(h);
  fin_.advance(h);
  time_s_ += h;
}

void GliderSimulator::command_fin_rad(double angle) {
  const double delay = dynamics_.vehicle().heading.fin_delay_s;
  if (!(delay > 0.0)) {
    fin_.set_target(angle);
    return;
  }
  if (pending_count_ == kMaxPendingFin) {  // a command per step at most: drop the oldest
    fin_.set_target(pending_fin_[pending_first_].angle_rad);
    pending_first_ = (pending_first_ + 1) % kMaxPendingFin;
    --pending_count_;
  }
  pending_fin_[(pending_first_ + pending_count_) % kMaxPendingFin] = {time_s_ + delay, angle};
  ++pending_count_;
}

void GliderSimulator::advance(double duration_s) {
  double remaining = duration_s;
  while (remaining > 1e-12) {
    while (pending_count_ > 0 && pending_fin_[pending_first_].due_s <= time_s_ + 1e-9) {
      fin_.set_target(pending_fin_[pending_first_].angle_rad);
      pending_first_ = (pending_first_ + 1) % kMaxPendingFin;
      --pending_count_;
    }
    const double h = remaining < step_s_ * (1.0 + 1e-9) ? remaining : step_s_;
    step(h);
    remaining -= h;
  }
}

Truth GliderSimulator::truth() const {
  const Evaluation e = dynamics_.evaluate(time_s_, state_, masses_after(0.0));
  Truth t;
  t.time_s = time_s_;
  t.east_m = state_[kEast];
  t.north_m = state_[kNorth];
  t.depth_m = state_[kZ];
  const double two_pi = 2.0 * std::numbers::pi;
  t.heading_rad = std::fmod(std::fmod(state_[kPsi], two_pi) + two_pi, two_pi);
  t.yaw_rate_rad_s = state_[kYawRate];
  t.pitch_rad = state_[kTheta];
  t.pitch_rate_rad_s = e.q;
  t.speed_m_s = e.speed_m_s;
  t.alpha_rad = e.alpha_rad;
  t.glide_path_rad = state_[kTheta] - e.alpha_rad;
  t.horizontal_speed_m_s = e.horizontal_speed_m_s;
  t.depth_rate_m_s = e.state_dot[kZ];
  t.net_buoyancy_kg = e.net_buoyancy_kg;
  t.pumped_volume_m3 = pump_.position();
  t.battery_pos_m = battery_.position();
  t.fin_rad = fin_.position();
  t.water = e.water;
  return t;
}

}  // namespace glider::model
