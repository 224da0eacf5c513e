// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/phases.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "glider/flightlog/columns.hpp"
#include "glider/flightlog/gaps.hpp"

namespace glider::flightlog {
namespace {

enum class State { kNone, kSurface, kDive, kClimb };  // what m_depth_state says, as far as used here

State state_at(std::span<const double> depth_state, std::size_t i) {
  if (depth_state.empty() || std::isnan(depth_state[i])) return State::kNone;
  switch (std::lround(depth_state[i])) {
    case 0:
      return State::kSurface;
    case 1:
      return State::kDive;
    case 2:
      return State::kClimb;
    default:
      return State::kNone;  // 3 hover: the motion tells; 99 abort (SIL) likewise
  }
}

Phase classify(double depth, double rate, State state, const PhaseOptions& o) {
  if (std::isnan(depth) || std::isnan(rate)) return Phase::kUnknown;
  const bool shallow = depth < o.surface_depth_m;
  if (state == State::kSurface && shallow) return Phase::kSurface;
  if (rate >= o.min_rate_m_s) return state == State::kClimb ? Phase::kInflection : Phase::kDive;
  if (rate <= -o.min_rate_m_s) return state == State::kDive ? Phase::kInflection : Phase::kClimb;
  return shallow ? Phase::kSurface : Phase::kInflection;
}

// Short inflections between two runs of the same glide join that glide.
void bridge_blips(std::span<const double> time, std::span<const double> depth, std::vector<Phase>& phases,
                  double bridge_s) {
  const std::vector<Segment> runs = find_segments(time, depth, phases);
  for (std::size_t k = 1; k + 1 < runs.size(); ++k) {
    const Segment& before = runs[k - 1];
    const Segment& after = runs[k + 1];
    const bool glide = before.phase == Phase::kDive || before.phase == Phase::kClimb;
    if (runs[k].phase == Phase::kInflection && glide && after.phase == before.phase &&
        after.start_s - before.end_s <= bridge_s) {
      std::fill(phases.begin() + static_cast<std::ptrdiff_t>(runs[k].first),
                phases.begin() + static_cast<std::ptrdiff_t>(runs[k].last + 1), before.phase);
    }
  }
}

}  // namespace

std::string_view to_string(Phase phase) {
  switch (phase) {
    case Phase::kSurface:
      return "surface";
    case Phase::kDive:
      return "dive";
    case Phase::kClimb:
      return "climb";
    case Phase::kInflection:
      return "inflection";
    case Phase::kUnknown:
      break;
  }
  return "unknown";
}

std::vector<Phase> classify_phases(std::span<const double> time, std::span<const double> depth_m,
                                   std::span<const double> depth_rate_m_s, std::span<const double> depth_state,
                                   const PhaseOptions& options) {
  if (depth_m.size() != time.size() || depth_rate_m_s.size() != time.size() ||
      (!depth_state.empty() && depth_state.size() != time.size())) {
    throw std::invalid_argument("classify_phases: time, depth, depth rate and depth state differ in length");
  }
  std::vector<Phase> phases(time.size());
  for (std::size_t i = 0; i < time.size(); ++i) {
    phases[i] = classify(depth_m[i], depth_rate_m_s[i], state_at(depth_state, i), options);
  }
  bridge_blips(time, depth_m, phases, options.bridge_s);
  return phases;
}

std::vector<Phase> classify_phases(const FlightLog& log, const PhaseOptions& options) {
  const std::optional<DepthSeries> series = depth_series(log);
  if (!series) {
    throw FlightLogError(log.source(), 0, "m_depth", 0, "no depth column (neither m_depth nor sci_water_pressure)");
  }
  const Column& time = log.time();
  const Column depth = interpolate_linear(time, series->depth_m, options.max_gap_s);
  Column rate = derive_depth_rate(time, depth, options.max_gap_s);
  if (const Column* logged = log.find("m_depth_rate")) {
    const Column filled = interpolate_linear(time, *logged, options.max_gap_s);
    for (std::size_t i = 0; i < rate.size(); ++i) {
      if (!std::isnan(filled[i])) rate[i] = filled[i];  // the glider's filtered rate where it has one
    }
  }
  Column state;
  if (const Column* logged = log.find("m_depth_state")) state = forward_fill(time, *logged, options.max_gap_s);
  return classify_phases(time, depth, rate, state, options);
}

std::vector<Segment> find_segments(std::span<const double> time, std::span<const double> depth_m,
                                   std::span<const Phase> phases) {
  if (depth_m.size() != time.size() || phases.size() != time.size()) {
    throw std::invalid_argument("find_segments: time, depth and phases differ in length");
  }
  std::vector<Segment> segments;
  for (std::size_t i = 0; i < phases.size(); ++i) {
    if (segments.empty() || segments.back().phase != phases[i]) {
      segments.push_back({phases[i], i, i, time[i], time[i], depth_m[i], depth_m[i]});
    } else {
      Segment& s = segments.back();
      s.last = i;
      s.end_s = time[i];
      s.end_depth_m = depth_m[i];
    }
  }
  return segments;
}

GlideCounts count_glides(std::span<const Segment> segments, double min_depth_change_m) {
  GlideCounts counts;
  for (const Segment& s : segments) {
    const double descent = s.end_depth_m - s.start_depth_m;  // NaN compares false: not counted
    if (s.phase == Phase::kDive && descent >= min_depth_change_m) ++counts.dives;
    if (s.phase == Phase::kClimb && -descent >= min_depth_change_m) ++counts.climbs;
  }
  return counts;
}

}  // namespace glider::flightlog
