// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/columns.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "glider/units.hpp"

namespace glider::flightlog {
namespace {

// The contract's column table, plus the SIL's own firmware columns.
constexpr auto kUnits = std::to_array<std::pair<std::string_view, std::string_view>>({
    {"m_present_time", "s"},
    {"m_depth", "m"},
    {"m_pitch", "rad"},
    {"m_roll", "rad"},
    {"m_heading", "rad"},
    {"c_heading", "rad"},
    {"m_fin", "rad"},
    {"c_fin", "rad"},
    {"m_ballast_pumped", "cc"},
    {"c_ballast_pumped", "cc"},
    {"m_de_oil_vol", "cc"},
    {"m_battpos", "in"},
    {"c_battpos", "in"},
    {"m_depth_rate", "m/s"},
    {"m_altitude", "m"},
    {"sci_water_pressure", "bar"},
    {"sci_water_temp", "degC"},
    {"sci_water_cond", "S/m"},
    {"m_gps_lat", "ddmm.mmmm"},
    {"m_gps_lon", "ddmm.mmmm"},
    {"m_lat", "ddmm.mmmm"},
    {"m_lon", "ddmm.mmmm"},
    {"m_water_vx", "m/s"},
    {"m_water_vy", "m/s"},
    {"m_vacuum", "inHg"},
    {"m_leakdetect_voltage", "V"},
    {"m_depth_state", "enum"},
    {"c_pitch", "rad"},
    {"x_yo_count", "count"},
    {"x_abort_cause", "enum"},
    {"x_loop_overruns", "count"},
});

}  // namespace

std::string_view unit_of(std::string_view column) {
  const auto* const it =
      std::find_if(kUnits.begin(), kUnits.end(), [column](const auto& entry) { return entry.first == column; });
  return it == kUnits.end() ? std::string_view{} : it->second;
}

std::optional<DepthSeries> depth_series(const FlightLog& log) {
  if (const Column* depth = log.find("m_depth")) return DepthSeries{*depth, "m_depth"};
  if (const Column* pressure = log.find("sci_water_pressure")) {
    DepthSeries series{*pressure, "sci_water_pressure"};
    for (double& value : series.depth_m) value = bar_to_approx_depth_m(value);  // NaN stays NaN
    return series;
  }
  return std::nullopt;
}

}  // namespace glider::flightlog
