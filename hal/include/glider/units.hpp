#pragma once
// The one place where Slocum's units (cc, inches, degrees) meet SI.
#include <numbers>

namespace glider {

constexpr double kCubicMetresPerCc = 1e-6;
constexpr double kMetresPerInch = 0.0254;
constexpr double kRadPerDeg = std::numbers::pi / 180.0;

constexpr double cc_to_m3(double cc) { return cc * kCubicMetresPerCc; }
constexpr double m3_to_cc(double m3) { return m3 / kCubicMetresPerCc; }
constexpr double in_to_m(double in) { return in * kMetresPerInch; }
constexpr double m_to_in(double m) { return m / kMetresPerInch; }
constexpr double deg_to_rad(double deg) { return deg * kRadPerDeg; }
constexpr double rad_to_deg(double rad) { return rad / kRadPerDeg; }

}  // namespace glider
