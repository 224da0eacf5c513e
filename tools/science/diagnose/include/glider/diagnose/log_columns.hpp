// SPDX-License-Identifier: Apache-2.0
#pragma once
// The one log-preparation step of the diagnosis: the columns both flight
// models read (with one rule for the fallbacks), the glide phases, and one
// definition of a yo. The steady model's observations (observations.hpp) and
// the dynamic model's track (track.hpp) are both built from it; they differ
// only in how a value is carried between the glider's cycles.
#include <optional>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"

namespace glider::diagnose {

// How a sparse column is carried between the cycles that logged it.
enum class Fill {
  kHold,         // the last value, up to max_age_s old (the steady model: one sample at a time)
  kInterpolate,  // linearly across gaps up to max_age_s (the dynamic model: the pump, slide and pitch move
                 // continuously; holding them would make a 4 s cycle look like a 2 s actuator lag)
};

struct LogColumns {
  // Per log row; NaN where the log has no value (or the column at all).
  flightlog::Column depth_m;  // m_depth, else bar_to_approx_depth_m(sci_water_pressure); linear across gaps
  flightlog::Column pitch_rad, ballast_cc, battpos_in, temperature_c;
  // sci_water_density where logged, else TEOS-10 from the CTD (conductivity, temperature, pressure).
  flightlog::Column density_kg_m3;
  std::vector<flightlog::Phase> phase;
  std::vector<flightlog::Segment> segments;
  // A yo is a dive of 3 m or more and everything up to the next one: a new
  // number at the start of every such dive, -1 before the first. Alternate
  // yos are fitted and held out, so both models must count them alike.
  std::vector<int> yo;
  bool has_battpos = false;
};

// A dive or climb shallower than this is a bob at the surface, not a glide.
inline constexpr double kMinGlideExcursionM = 3.0;

// nullopt when the log has no depth (neither m_depth nor sci_water_pressure).
// The depth is interpolated across gaps up to depth_max_gap_s; every other
// column is carried by `fill` up to fill_max_age_s.
std::optional<LogColumns> read_log_columns(const flightlog::FlightLog& log, Fill fill, double fill_max_age_s,
                                           double depth_max_gap_s);

}  // namespace glider::diagnose
