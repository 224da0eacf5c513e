// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which part of a yo each sample belongs to, from depth and depth rate, with
// m_depth_state (1 dive, 2 climb, 3 hover, 0 surface) as a hint when the log
// has it. Deliberately simple; the rules, in order, for each sample:
//   - depth or depth rate empty                       -> unknown
//   - state 0 and shallower than surface_depth_m      -> surface
//   - descending at >= min_rate_m_s                   -> dive, unless the state says climb -> inflection
//   - ascending at >= min_rate_m_s                    -> climb, unless the state says dive -> inflection
//   - slower, shallower than surface_depth_m          -> surface
//   - slower, deeper                                  -> inflection
// then an inflection shorter than bridge_s between two dives (or two climbs)
// becomes part of them: a one-cycle hover or a slow sample inside a glide
// is not a turn. "Inflection" thus means the vehicle is turning (state and
// motion disagree while the pump moves) or barely moving at depth. In the real
// logs state 0 also covers the last metres of a climb and the first of a dive
// (the glider is already under way): the motion decides there.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "glider/flightlog/flight_log.hpp"

namespace glider::flightlog {

enum class Phase : std::uint8_t { kUnknown, kSurface, kDive, kClimb, kInflection };
std::string_view to_string(Phase phase);

struct PhaseOptions {
  double surface_depth_m = 1.0;  // the real logs read 0-0.9 m while at the surface
  double min_rate_m_s = 0.05;    // glides are 0.10-0.20 m/s; m_depth_rate noise ~0.03 m/s
  double bridge_s = 20.0;        // a few cycles at the real logs' 4.3-4.5 s
  // Log version only: depth and rate are interpolated, and the state carried,
  // over gaps up to this long (longer gaps are surfacings: left unknown).
  double max_gap_s = 30.0;
};

// depth_state may be empty (the log has none); its values other than 0-3
// (e.g. the SIL's 99 = abort) are ignored. All non-empty spans have the same
// length (std::invalid_argument otherwise).
std::vector<Phase> classify_phases(std::span<const double> time, std::span<const double> depth_m,
                                   std::span<const double> depth_rate_m_s, std::span<const double> depth_state,
                                   const PhaseOptions& options = {});

// The same on a log: depth from depth_series() interpolated over max_gap_s;
// rate from m_depth_rate where the log has it, else derive_depth_rate();
// m_depth_state forward-filled over max_gap_s. Throws FlightLogError when the
// log has no depth column.
std::vector<Phase> classify_phases(const FlightLog& log, const PhaseOptions& options = {});

// A run of samples with the same phase.
struct Segment {
  Phase phase = Phase::kUnknown;
  std::size_t first = 0;  // sample indices, inclusive
  std::size_t last = 0;
  double start_s = 0.0;
  double end_s = 0.0;
  double start_depth_m = 0.0;  // NaN if the depth is empty there
  double end_depth_m = 0.0;
};
std::vector<Segment> find_segments(std::span<const double> time, std::span<const double> depth_m,
                                   std::span<const Phase> phases);

// Dives that went down, and climbs that went up, by at least
// min_depth_change_m: a surface bob or a short aborted dive is not a glide.
struct GlideCounts {
  std::size_t dives = 0;
  std::size_t climbs = 0;
};
GlideCounts count_glides(std::span<const Segment> segments, double min_depth_change_m = 3.0);

}  // namespace glider::flightlog
