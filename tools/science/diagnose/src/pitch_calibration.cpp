// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/pitch_calibration.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

namespace glider::diagnose {
namespace {

void check(const PitchCalibration& c) {
  if (!(c.scale >= PitchCalibration::kMinScale && c.scale <= PitchCalibration::kMaxScale)) {
    char text[160];
    std::snprintf(text, sizeof text, "pitch calibration scale %g outside [%g, %g]", c.scale,
                  PitchCalibration::kMinScale, PitchCalibration::kMaxScale);
    throw std::invalid_argument(text);
  }
  if (!(std::abs(c.offset_rad) <= PitchCalibration::kMaxAbsOffsetRad)) {
    char text[160];
    std::snprintf(text, sizeof text, "pitch calibration offset %g rad outside [%g, %g] rad", c.offset_rad,
                  -PitchCalibration::kMaxAbsOffsetRad, PitchCalibration::kMaxAbsOffsetRad);
    throw std::invalid_argument(text);
  }
}

}  // namespace

std::string PitchCalibration::describe() const {
  if (!active()) return "none (m_pitch as logged)";
  char text[96];
  std::snprintf(text, sizeof text, "%.6g m_pitch %s %.6g rad", scale, offset_rad < 0.0 ? "-" : "+",
                std::abs(offset_rad));
  return text;
}

flightlog::FlightLog calibrate_pitch(const flightlog::FlightLog& log, const PitchCalibration& calibration) {
  check(calibration);
  if (!calibration.active() || !log.has("m_pitch")) return log;
  const std::vector<std::string>& names = log.column_names();
  std::vector<flightlog::Column> columns;
  columns.reserve(names.size());
  std::size_t time_index = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const flightlog::Column& column = log.column(names[i]);
    if (&column == &log.time()) time_index = i;
    columns.push_back(column);
    if (names[i] != "m_pitch") continue;
    for (double& pitch : columns.back()) pitch = calibration.scale * pitch + calibration.offset_rad;  // NaN stays NaN
  }
  flightlog::FlightLog calibrated(log.source(), log.metadata(), names, std::move(columns), time_index);
  calibrated.set_end(log.end());
  return calibrated;
}

}  // namespace glider::diagnose
