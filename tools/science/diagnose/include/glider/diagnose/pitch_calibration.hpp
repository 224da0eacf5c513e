// SPDX-License-Identifier: Apache-2.0
#pragma once
// A calibration of the glider's pitch sensor, applied to the logged m_pitch
// before anything is diagnosed: pitch = scale * m_pitch + offset. An explicit,
// switchable prior (issue 26): off unless asked for (glider-diagnose
// --pitch-scale / --pitch-offset), and stated in the diagnosis when on.
//
// Why it matters: a steady glide at a measured depth rate w balances drag
// against the along-path weight, so the drag fitted to w goes as
// sin^3(glide angle): comet's raw m_pitch against the pitch gliderflight's
// authors tilt-corrected (0.86 m_pitch - 0.004 rad, Merckelbach et al. 2019)
// is drag 1.40 against 0.92 on the same dives (docs/science.md).
#include <string>

#include "glider/flightlog/flight_log.hpp"

namespace glider::diagnose {

struct PitchCalibration {
  double scale = 1.0;
  double offset_rad = 0.0;
  // Allowed: a sensor reading within a factor of two of the hull's pitch, offsets within 0.2 rad (11 deg).
  static constexpr double kMinScale = 0.5, kMaxScale = 2.0, kMaxAbsOffsetRad = 0.2;
  bool active() const { return scale != 1.0 || offset_rad != 0.0; }
  // "0.86 m_pitch - 0.004 rad", or "none (m_pitch as logged)".
  std::string describe() const;
};

// `log` with its m_pitch column calibrated (a copy; the log unchanged when
// the calibration is not active or the log has no m_pitch). Throws
// std::invalid_argument naming the value and its allowed range when the
// calibration is not finite or outside them.
flightlog::FlightLog calibrate_pitch(const flightlog::FlightLog& log, const PitchCalibration& calibration);

}  // namespace glider::diagnose
