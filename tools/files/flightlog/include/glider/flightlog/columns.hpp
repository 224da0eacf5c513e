// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the flight-log contract (docs/flight-log.md) says about its columns,
// and the depth series every analysis starts from.
#include <optional>
#include <string>
#include <string_view>

#include "glider/flightlog/flight_log.hpp"

namespace glider::flightlog {

// Unit of a column of the contract's table ("rad", "cc", ...); empty for a
// column the contract does not name (sim_* columns are SI, see their names).
std::string_view unit_of(std::string_view column);

// Depth from the CTD's gauge pressure: glider::bar_to_approx_depth_m (units.hpp),
// 1 dbar taken as 1 m. The true factor is 1e4 Pa / (rho g) = 0.992 m (rho
// 1028 kg/m^3) to 1.014 m (Baltic, 1005 kg/m^3): within 1.5 %, well below the
// CTD's lag behind m_depth in the real logs (1.3-1.5 s, 0.2-0.4 m).

struct DepthSeries {
  Column depth_m;      // + down, NaN where the source column is empty
  std::string source;  // "m_depth" or "sci_water_pressure"
};

// m_depth when the log has that column, else bar_to_approx_depth_m of
// sci_water_pressure; nullopt when it has neither. The two are not mixed
// within one log: they differ by the CTD's lag and offset.
std::optional<DepthSeries> depth_series(const FlightLog& log);

}  // namespace glider::flightlog
