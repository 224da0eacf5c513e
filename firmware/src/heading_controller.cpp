#include "glider/firmware/heading_controller.hpp"

#include <algorithm>
#include <cmath>

#include "glider/firmware/geo.hpp"

namespace glider::fw {

double HeadingController::clamp_fin(double fin) const {
  return std::clamp(fin, -config_.fin_max_rad, config_.fin_max_rad);
}

double HeadingController::update(double heading_rad, double target_rad, double dt_s) {
  if (!(dt_s > 0.0)) return fin_;
  // Heading rate from successive readings (1 Hz): the compass is smooth
  // enough (0.2 deg noise) that no further filtering is needed at 1 Hz.
  rate_ = have_heading_ ? wrap_pi(heading_rad - last_heading_) / dt_s : 0.0;
  last_heading_ = heading_rad;
  have_heading_ = true;
  const double rate_used = std::fabs(rate_) < config_.rate_deadband_rad_s ? 0.0 : rate_;

  switch (config_.law) {
    case HeadingLaw::kProportional:
      fin_ = clamp_fin(config_.kp * wrap_pi(target_rad - heading_rad));
      return fin_;
    case HeadingLaw::kSlocum: {
      const double error = wrap_pi(target_rad - heading_rad);
      integrator_ += config_.igain * error * dt_s;
      fin_ = clamp_fin(config_.gain * error + integrator_ + config_.dgain * rate_used);
      return fin_;
    }
    case HeadingLaw::kCompensated: {
      // Where the heading will be when a fin moved now takes effect.
      const double predicted = heading_rad + rate_used * config_.delay_s;
      double error = wrap_pi(target_rad - predicted);
      if (std::fabs(error) < config_.error_deadband_rad) error = 0.0;
      const double unsaturated = config_.gain * error + integrator_ + config_.dgain * rate_used;
      const bool saturated_high = unsaturated >= config_.fin_max_rad;
      const bool saturated_low = unsaturated <= -config_.fin_max_rad;
      const double step = config_.igain * error * dt_s;
      // Anti-windup: while saturated, the integrator may only move the fin
      // back inside its travel.
      if (!(saturated_high && step > 0.0) && !(saturated_low && step < 0.0)) integrator_ += step;
      integrator_ = clamp_fin(integrator_);
      const double wanted = clamp_fin(config_.gain * error + integrator_ + config_.dgain * rate_used);
      // Never ask more of the servo than it can do in one cycle: the command
      // then is where the fin really is, and the D term sees its true effect.
      const double max_step = config_.fin_rate_rad_s * dt_s;
      fin_ = std::clamp(wanted, fin_ - max_step, fin_ + max_step);
      return fin_;
    }
  }
  return fin_;
}

}  // namespace glider::fw
