// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/columns.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "glider/hal/log_record.hpp"
#include "glider/hal/sim_log_columns.hpp"
#include "glider/units.hpp"

namespace glider::flightlog {
namespace {

// Columns of real Slocum logs that neither the firmware nor the SIL writes;
// theirs come from the one schema (hal::kLogColumns, hal::kSimLogColumns).
constexpr auto kOtherUnits = std::to_array<std::pair<std::string_view, std::string_view>>({
    {"m_de_oil_vol", "cc"},
    {"m_altitude", "m"},
    {"m_vacuum", "inHg"},
    {"m_leakdetect_voltage", "V"},
});

}  // namespace

std::string_view unit_of(std::string_view column) {
  for (const hal::LogColumn& c : hal::kLogColumns) {
    if (c.name == column) return c.unit;
  }
  for (const hal::SimLogColumn& c : hal::kSimLogColumns) {
    if (c.name == column) return c.unit;
  }
  const auto* const it = std::find_if(kOtherUnits.begin(), kOtherUnits.end(),
                                      [column](const auto& entry) { return entry.first == column; });
  return it == kOtherUnits.end() ? std::string_view{} : it->second;
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
