// SPDX-License-Identifier: Apache-2.0
#pragma once
// Heading-control figures of a flight log: steady error per glide
// direction, the oscillation about it (amplitude and period), RMS error and
// fin activity. The same numbers for a real Slocum log and a SIL log.
#include <cmath>
#include <string>

#include "glider/flightlog/flight_log.hpp"

namespace glider::heading_study {

struct HeadingMetrics {
  std::size_t samples = 0;
  double dive_error_deg = 0.0;  // median m_heading - c_heading on dives (+ = clockwise of the command)
  double climb_error_deg = 0.0;
  double rms_error_deg = 0.0;
  double oscillation_amplitude_deg = 0.0;  // median over glides of sqrt(2) * std about the glide's mean
  double oscillation_period_s = 0.0;       // median time between upward crossings of that (2 deg hysteresis)
  double fin_travel_rad_per_h = 0.0;       // sum |change of c_fin| per hour of gliding
  // Heading change across the inflections (median, deg, + clockwise), from
  // the glide's last row 12 s before its end to 35 s after, dive -> climb
  // and climb -> dive; and the part of it the pitch-over itself makes on a
  // rolled glider (the sum of d(pitch) tan(roll) / cos(pitch): Euler's
  // kinematics), from the logged m_pitch and m_roll. NaN without them.
  double inflection_turn_deg[2] = {std::nan(""), std::nan("")};
  double inflection_kinematic_deg[2] = {std::nan(""), std::nan("")};
};

// Rows in a dive or climb with a heading command, after `skip_s` from the
// log's start (the first turn onto the heading is not steady flight).
HeadingMetrics heading_metrics(const flightlog::FlightLog& log, double skip_s);

std::string format(const HeadingMetrics& m);
// The inflection turns: "inflection turn dive->climb X (pitch-over Y), climb->dive ...".
std::string format_inflections(const HeadingMetrics& m);

}  // namespace glider::heading_study
