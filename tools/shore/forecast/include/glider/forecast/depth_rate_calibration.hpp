// SPDX-License-Identifier: Apache-2.0
#pragma once
// The glider's steady-glide depth rates against the model's (docs/forecast.md,
// "The depth-rate calibration"): what the model must change to glide down and
// up as fast as the glider did at the pitch and pump it logged.
//
// Why the depth rate: it is the one speed the glider measures itself (its
// pressure sensor), for both kinds of pitch control. Its dead-reckoned speed
// is counted through its pitch sensor, and with the pitch servo on (Slocum's
// d_/c_use_pitch 3) its logged pitch is the commanded one whatever its sensor
// reads: comet-2016's servo held m_pitch at 25 deg while its hull, by its
// sensor's scale (~0.86), glided near 22 deg, flatter and slower than a model
// holding 25. Two rates (dives and climbs) explain two unknowns:
// - with the servo: the sensor's scale (the hull's pitch is scale x m_pitch;
//   the runs command the mission's pitch x scale, the hull the glider flew)
//   and the net buoyancy's offset;
// - with the battery fixed: the hull's pitch is the trim's, which the model
//   flies, so the drag and the buoyancy's offset.
// Solved on the model's steady-glide polar (model::PitchGlideSolver), each
// direction's net buoyancy first read from the model's own flight at its own
// pitch, so the model's depth-dependent buoyancy and its pump cancel.
#include <string>

#include "glider/forecast/glide_pitch.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::forecast {

struct DepthRateCalibration {
  bool have = false;
  bool servo = false;
  double glider_dive_m_s = 0.0, glider_climb_m_s = 0.0;  // steady |depth rate|
  double model_dive_m_s = 0.0, model_climb_m_s = 0.0;
  double pitch_scale = 1.0;  // servo: hull pitch = pitch_scale x m_pitch
  // servo: the mission's commanded dive / climb pitch times these (the hull
  // the glider flew over the model's); 1 with the battery fixed
  double dive_pitch_factor = 1.0, climb_pitch_factor = 1.0;
  double drag_factor = 1.0;  // battery fixed: the vehicle's drag times this
  double buoyancy_kg = 0.0;  // added to the vehicle's buoyancy offset (+ heavy)
  std::string why_not;       // without `have`: why
};

// Scales outside these are not explained by the named cause.
inline constexpr double kDepthRateScaleMin = 0.67, kDepthRateScaleMax = 1.5;
inline constexpr double kDepthRateDragMin = 0.5, kDepthRateDragMax = 2.5;
inline constexpr double kDepthRateBuoyancyMaxKg = 0.3;
inline constexpr int kDepthRateMinSamples = 20;  // per direction

// From the glider's steady glides and the model's still-water flight (the
// same GlidePitch rule), for the vehicle's hydrodynamics at `density`.
DepthRateCalibration calibrate_depth_rates(const model::Hydrodynamics& hydro, double density_kg_m3,
                                           const GlidePitch& glider, const GlidePitch& model, bool servo);

}  // namespace glider::forecast
