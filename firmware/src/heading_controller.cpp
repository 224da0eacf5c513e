// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/heading_controller.hpp"

#include <algorithm>
#include <cmath>

#include "glider/firmware/geo.hpp"

namespace glider::fw {

double HeadingController::clamp_fin(double fin) const {
  return std::clamp(fin, -config_.fin_max_rad, config_.fin_max_rad);
}

void HeadingController::select_glide(bool diving) {
  if (config_.law != HeadingLaw::kCompensated || diving == diving_) return;
  std::swap(integrator_, other_integrator_);
  diving_ = diving;
}

double HeadingController::update_compensated(double heading_rad, double target_rad, double dt_s, double rate,
                                             double speed_m_s) {
  // The fin's yaw authority now (rad/s of yaw rate per rad of fin); 0 when
  // unknown, and then the predictor falls back on the measured rate alone.
  const double authority = config_.yaw_gain_per_m * speed_m_s;
  const auto steps = std::min<std::size_t>(static_cast<std::size_t>(std::lround(config_.delay_s / dt_s)), kHistory - 1);
  // history_ holds the commands of the last cycles, newest at k = 0: the
  // one acting now was sent `steps` cycles ago.
  auto sent = [this](std::size_t k) { return history_[(history_next_ + kHistory - 1 - k) % kHistory]; };
  const double acting = steps > 0 ? sent(steps - 1) : fin_;
  double in_the_pipe = 0.0;  // sum of the commands that will act over the next dead time
  for (std::size_t k = 0; k < steps; ++k) in_the_pipe += sent(k);
  double predicted = 0.0;
  double predicted_rate = 0.0;
  if (authority > 0.0) {
    // Smith predictor: the turn rate the fin does not explain (static roll,
    // current shear) is a slow disturbance, filtered hard; the fin's part is
    // known from the commands themselves.
    const double blend = dt_s / (config_.disturbance_filter_s + dt_s);
    disturbance_ += blend * (rate - authority * acting - disturbance_);
    predicted = heading_rad + authority * in_the_pipe * dt_s + disturbance_ * config_.delay_s;
    predicted_rate = authority * fin_ + disturbance_;
  } else {
    const double blend = dt_s / (config_.rate_filter_s + dt_s);
    filtered_rate_ += blend * (rate - filtered_rate_);
    predicted = heading_rad + filtered_rate_ * config_.delay_s;
    predicted_rate = filtered_rate_;
  }
  double error = wrap_pi(target_rad - predicted);
  if (std::fabs(error) < config_.error_deadband_rad) error = 0.0;
  const double damping = config_.dgain * predicted_rate;
  const double unsaturated = config_.gain * error + integrator_ + damping;
  const double step = config_.igain * error * dt_s;
  // Anti-windup: while saturated, the integrator may only move the fin back
  // inside its travel.
  const bool pushes_out =
      (unsaturated >= config_.fin_max_rad && step > 0.0) || (unsaturated <= -config_.fin_max_rad && step < 0.0);
  if (!pushes_out) integrator_ = clamp_fin(integrator_ + step);
  const double wanted = clamp_fin(config_.gain * error + integrator_ + damping);
  if (std::fabs(wanted - fin_) < config_.fin_deadband_rad) return fin_;
  // Never ask more of the servo than it can do in one cycle: the command
  // then is where the fin really is, and the predictor's history is true.
  const double max_step = config_.fin_rate_rad_s * dt_s;
  return std::clamp(wanted, fin_ - max_step, fin_ + max_step);
}

double HeadingController::update(double heading_rad, double target_rad, double dt_s, double speed_m_s) {
  if (!(dt_s > 0.0)) return fin_;
  // Heading rate from successive readings (1 Hz).
  rate_ = have_heading_ ? wrap_pi(heading_rad - last_heading_) / dt_s : 0.0;
  last_heading_ = heading_rad;
  have_heading_ = true;
  const double rate_used = std::fabs(rate_) < config_.rate_deadband_rad_s ? 0.0 : rate_;

  switch (config_.law) {
    case HeadingLaw::kProportional:
      fin_ = clamp_fin(config_.kp * wrap_pi(target_rad - heading_rad));
      break;
    case HeadingLaw::kSlocum: {
      const double error = wrap_pi(target_rad - heading_rad);
      if (rate_used == 0.0 && std::fabs(error) < config_.heading_deadband_rad) break;  // held
      integrator_ += config_.igain * error * dt_s;
      fin_ = clamp_fin(config_.gain * error + integrator_ + config_.dgain * rate_used);
      break;
    }
    case HeadingLaw::kCompensated:
      fin_ = update_compensated(heading_rad, target_rad, dt_s, rate_, speed_m_s);
      break;
  }
  history_[history_next_] = fin_;
  history_next_ = (history_next_ + 1) % kHistory;
  return fin_;
}

}  // namespace glider::fw
