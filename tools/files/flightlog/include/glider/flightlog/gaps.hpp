// SPDX-License-Identifier: Apache-2.0
#pragma once
// Explicit gap handling for log columns. An empty sample (NaN) means the
// glider logged no new value in that cycle; what a tool may put there depends
// on the variable, so each tool picks one of these and says which. Every
// function returns a new column of the same length, keeps every valid sample
// unchanged, and never fills across a gap longer than its limit: the real logs
// have 20-230 s surface gaps (GPS, Iridium) over which the vehicle state
// changes, e.g. the pump goes from -230 cc to +230 cc.
// All throw std::invalid_argument when time and values differ in length.
#include <span>

#include "glider/flightlog/flight_log.hpp"

namespace glider::flightlog {

// Step-held values (commands, pump volume, battery position, m_depth_state):
// an empty sample takes the last valid value while that value is at most
// max_age_s old, and stays empty after that. Samples before the first valid
// one stay empty.
Column forward_fill(std::span<const double> time, std::span<const double> values, double max_age_s);

// Continuous measurements (depth, pitch, temperature): an empty sample gets
// the straight line between the valid samples either side of it, when those
// two are at most max_gap_s apart. No extrapolation before the first or after
// the last valid sample.
Column interpolate_linear(std::span<const double> time, std::span<const double> values, double max_gap_s);

// Angles in radians (m_heading, [0, 2 pi)): as interpolate_linear, but along
// the shorter arc and wrapped to [0, 2 pi), so a gap across north (6.2 to 0.1
// rad) is filled near north, not swung through south.
Column interpolate_angle_rad(std::span<const double> time, std::span<const double> values, double max_gap_s);

// d(depth)/dt [m/s, + descending] where the log has no m_depth_rate: centred
// difference over the neighbouring valid depth samples, one-sided where only
// one neighbour is within max_gap_s, empty where the depth is empty or no
// neighbour is within max_gap_s. Not filtered: the glider's own m_depth_rate
// is smoother.
Column derive_depth_rate(std::span<const double> time, std::span<const double> depth, double max_gap_s);

}  // namespace glider::flightlog
