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
