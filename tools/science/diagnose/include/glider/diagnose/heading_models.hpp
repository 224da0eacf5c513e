// SPDX-License-Identifier: Apache-2.0
#pragma once
// The three links of the heading loop as the diagnosis replays them on a
// log (heading_effects.hpp), each with the effects of its link applied:
// - the servo: m_fin from the logged c_fin through the vehicle's dead time
//   and fin speed;
// - the vehicle: the yaw rate from the logged m_fin, speed, lift factor and
//   roll through the model's first-order yaw (model/dynamics.hpp), compared
//   through the same slope estimator as the measured yaw rate;
// - the autopilot: c_fin from the logged heading and command by Slocum's law
//   (fin = gain e + integral + dgain r, clamped; firmware/heading_controller).
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "glider/diagnose/heading_effects.hpp"
#include "glider/diagnose/heading_track.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

// The autopilot a log's header configures (u_hd_fin_ap_*), as nominal values.
struct AutopilotSettings {
  double gain = 1.5, igain = 0.02, dgain = -4.0;  // the firmware's defaults (Slocum's in the comet logs)
  double rate_deadband_rad_s = 0.0087;
  double heading_deadband_rad = 0.0;  // u_heading_deadband: 0 = the fin is never held
  bool stated = false;                // false: the log's header states none (the defaults stand in)
};

// Slocum's heading law, one cycle: the fin held (output unchanged, nothing
// integrated) inside both deadbands, else PID with the integrator unclamped
// and only the output clamped, as the firmware's. The open-loop replay
// (predict_autopilot_fin) and the closed loop (fly_closed_loop) both step it.
struct AutopilotLaw {
  double kp = 0.0, ki = 0.0, kd = 0.0, hold_below = 0.0, rate_deadband = 0.0, fin_max = 0.0;
  double integrator = 0.0, output = 0.0;
  // The law with the values' gains, deadband and this log's fin limit.
  static AutopilotLaw from(const HeadingValues& values, const AutopilotSettings& settings, double fin_max_rad);
  double step(double error, double rate, double dt) {
    if (std::abs(rate) < rate_deadband) {
      rate = 0.0;
      if (std::abs(error) < hold_below) return output;
    }
    integrator += ki * error * dt;
    output = std::clamp(kp * error + integrator + kd * rate, -fin_max, fin_max);
    return output;
  }
};

// The values that mean "no effect" for this vehicle and configured law.
HeadingValues nominal_heading_values(const model::VehicleParams& vehicle, const AutopilotSettings& autopilot);

// Rows of the log (indices into row_*) where each link can be scored: the
// servo where m_fin and c_fin are logged under water, the autopilot where
// c_fin is logged under a heading command.
std::vector<std::size_t> servo_rows(const HeadingTrack& track);
std::vector<std::size_t> autopilot_rows(const HeadingTrack& track);

// Predictions at `rows` / `samples` (sorted); NaN where the model has none.
void predict_servo_fin(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                       std::span<const std::size_t> rows, std::vector<double>& out);
void predict_autopilot_fin(const HeadingTrack& track, const AutopilotSettings& settings, const HeadingValues& values,
                           std::span<const std::size_t> rows, std::vector<double>& out);
void predict_yaw_rate(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                      std::span<const std::size_t> samples, std::vector<double>& out);

}  // namespace glider::diagnose
