// SPDX-License-Identifier: Apache-2.0
#include "glider/model/simulator.hpp"

#include <algorithm>
#include <boost/numeric/odeint/external/eigen/eigen_algebra.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <cmath>

#include <numbers>

#include "glider/model/first_order_lag.hpp"
#include "glider/model/root_finding.hpp"
#include "glider/model/stable_step.hpp"

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
      step_s_(stable_step_s(dynamics_, step_s)),  // a stiff vehicle gets a shorter step, never NaN
      surface_zone_m_(vehicle.hull_diameter_m + kSurfaceZoneMarginM),
      pump_(vehicle.ballast.volume_min_m3, vehicle.ballast.volume_max_m3, vehicle.ballast.rate_m3_s, 0.0),
      battery_(make_slide(vehicle.battery, 0.0)),
      second_(make_slide(vehicle.second_mass, 0.0)),
      fin_(-vehicle.heading.fin_max_rad, vehicle.heading.fin_max_rad, vehicle.heading.fin_rate_rad_s, 0.0) {}

double GliderSimulator::displaced_pump_volume_after(double t) const {
  const double lag = dynamics_.vehicle().ballast.lag_s;
  if (!(lag > 0.0)) return pump_.position_after(t);
  // The servo's path over a step is linear (no step carries a servo's
  // stop, see advance()): the lag of a linear input is exact.
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
  current_.reset();
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
  current_.reset();
}

const Evaluation& GliderSimulator::current() const {
  if (!current_) current_ = dynamics_.evaluate(time_s_, state_, masses_after(0.0), &mass_cache_);
  return *current_;
}

void GliderSimulator::step(double h) {
  Stepper stepper;
  // The servos' paths over [t, t + h] are closed-form: evaluate them at each
  // RK4 stage time instead of holding them constant over the step.
  const double t0 = time_s_;
  auto rhs = [this, t0](const State& s, State& ds, double t) {
    ds = dynamics_.evaluate(t, s, masses_after(t - t0), &mass_cache_).state_dot;
  };
  // The first stage is the derivative at the current state: current() has it
  // when the log or the sensors asked for it this cycle.
  stepper.do_step(rhs, state_, current().state_dot, t0, h);
  current_.reset();
  displaced_pump_volume_m3_ = displaced_pump_volume_after(h);
  pump_.advance(h);
  battery_.advance(h);
  second_.advance(h);
  fin_.advance(h);
  time_s_ += h;
}

void GliderSimulator::retarget(RateLimitedServo& servo, double target) {
  const double before = servo.target();
  servo.set_target(target);
  if (servo.target() != before) current_.reset();
}

void GliderSimulator::retarget_fin(double angle) {
  if (std::abs(angle - fin_.position()) <= dynamics_.vehicle().heading.fin_deadband_rad) return;
  retarget(fin_, angle);
}

void GliderSimulator::command_fin_rad(double angle) {
  const double delay = dynamics_.vehicle().heading.fin_delay_s;
  if (!(delay > 0.0)) {
    retarget_fin(angle);
    return;
  }
  if (pending_count_ == kMaxPendingFin) {  // a command per step at most: drop the oldest
    retarget_fin(pending_fin_[pending_first_].angle_rad);
    pending_first_ = (pending_first_ + 1) % kMaxPendingFin;
    --pending_count_;
  }
  pending_fin_[(pending_first_ + pending_count_) % kMaxPendingFin] = {time_s_ + delay, angle};
  ++pending_count_;
}

void GliderSimulator::advance(double duration_s) {
  double remaining = duration_s;
  while (remaining > 1e-12) {
    apply_due_fin_commands();
    // Near the surface the waterplane makes the heave mode fast: the step
    // there is at most kSurfaceStepS (see the header).
    const double max_h = state_[kZ] < surface_zone_m_ ? std::min(step_s_, kSurfaceStepS) : step_s_;
    double h = remaining < max_h * (1.0 + 1e-9) ? remaining : max_h;
    // A fin command waiting out its dead time starts the servo exactly when
    // due: the step ends there (not at the next step boundary).
    if (pending_count_ > 0) h = step_until(pending_fin_[pending_first_].due_s - time_s_, h);
    // Nor does a step carry a servo's stop inside it: the masses' path (and
    // the pump lag's input) is then smooth over every step, as RK4 needs.
    for (const RateLimitedServo* servo : {&pump_, &battery_, &second_, &fin_})
      h = step_until(servo->time_to_target(), h);
    step(h);
    remaining -= h;
  }
}

double GliderSimulator::step_until(double event_s, double h) {
  // Events closer than kMinEventStepS are left inside the step (a servo
  // rounding its last micrometre), as are those at its end.
  return event_s > kMinEventStepS && event_s < h * (1.0 - 1e-9) ? event_s : h;
}

void GliderSimulator::apply_due_fin_commands() {
  while (pending_count_ > 0 && pending_fin_[pending_first_].due_s <= time_s_ + 1e-9) {
    retarget_fin(pending_fin_[pending_first_].angle_rad);
    pending_first_ = (pending_first_ + 1) % kMaxPendingFin;
    --pending_count_;
  }
}

Truth GliderSimulator::truth() const {
  const Evaluation& e = current();
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
