// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one place where Slocum's units (cc, inches, degrees) meet SI.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>

namespace glider {

constexpr double kCubicMetresPerCc = 1e-6;
constexpr double kMetresPerInch = 0.0254;
constexpr double kRadPerDeg = std::numbers::pi / 180.0;
constexpr double kDbarPerBar = 10.0;
constexpr double kPascalPerBar = 1e5;
// Slocum's own depth from pressure where a log has no m_depth: 1 dbar taken as
// 1 m of sea water (true to ~1 % in the upper 200 m; the model uses TEOS-10).
constexpr double kApproxMetresPerBar = 10.0;

constexpr double cc_to_m3(double cc) { return cc * kCubicMetresPerCc; }
constexpr double m3_to_cc(double m3) { return m3 / kCubicMetresPerCc; }
constexpr double in_to_m(double in) { return in * kMetresPerInch; }
constexpr double m_to_in(double m) { return m / kMetresPerInch; }
constexpr double deg_to_rad(double deg) { return deg * kRadPerDeg; }
constexpr double rad_to_deg(double rad) { return rad / kRadPerDeg; }
constexpr double bar_to_dbar(double bar) { return bar * kDbarPerBar; }
constexpr double bar_to_pa(double bar) { return bar * kPascalPerBar; }
constexpr double bar_to_approx_depth_m(double bar) { return bar * kApproxMetresPerBar; }

// Fixed-point register values of the Modbus actuators: a register holds
// round(value * counts_per_unit) as a signed 16-bit count (boards/modbus_actuators.md).
constexpr double counts_to_value(std::int16_t counts, double counts_per_unit) {
  return static_cast<double>(counts) / counts_per_unit;
}
// Empty when the value does not fit a signed 16-bit register (never wrapped).
inline std::optional<std::int16_t> value_to_counts(double value, double counts_per_unit) {
  const double counts = std::round(value * counts_per_unit);
  if (!(counts >= -32768.0 && counts <= 32767.0)) return std::nullopt;  // also NaN
  return static_cast<std::int16_t>(counts);
}

}  // namespace glider
