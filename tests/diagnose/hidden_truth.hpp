// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the hidden-effect tests and bench_diagnose_coverage share, free of any
// test framework: platform-independent draws, the waters the effects are hidden
// in, and the truths only the flown log knows (its sim_* columns check the
// analysis, never feed it).
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/model/environment.hpp"

namespace glider::hidden {

// Uniform in [lo, hi) from the top 53 bits: the same draw on every platform
// (std::uniform_real_distribution does not promise that).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng() >> 11) / 9007199254740992.0;
}

// Water given by temperature and salinity nodes {depth m, degC, PSS-78}:
// density from TEOS-10, and a CTD can be simulated in it.
inline model::Environment ts_water(const std::vector<std::array<double, 3>>& depth_t_s) {
  std::vector<model::ProfileNode> nodes;
  for (const auto& [depth, t, s] : depth_t_s) {
    model::ProfileNode node;
    node.depth_m = depth;
    node.water.temperature_c = t;
    node.water.practical_salinity = s;
    nodes.push_back(node);
  }
  return model::Environment{model::WaterColumn(std::move(nodes), model::Oscillation{})};
}

// Still 1025 kg/m^3 water moving vertically at w (+ down) between 25 and 45 m,
// ramping from 20 m and to 50 m: an internal wave's or a front's layer.
inline model::Environment vertical_velocity_layer(double w_m_s) {
  const std::vector<model::ProfileNode> nodes{{20.0, {1025.0, 10.0, 0.0, 0.0, 0.0}},
                                              {25.0, {1025.0, 10.0, 0.0, 0.0, w_m_s}},
                                              {45.0, {1025.0, 10.0, 0.0, 0.0, w_m_s}},
                                              {50.0, {1025.0, 10.0, 0.0, 0.0, 0.0}}};
  return model::Environment{model::WaterColumn(nodes, model::Oscillation{})};
}

// The simulator's vertical water velocity averaged over the log's glide
// samples (m_depth_state dive or climb, below 2 m): what the diagnosis's
// log-mean value estimates.
inline double glide_mean_vertical_velocity(const flightlog::FlightLog& log) {
  const auto& w = log.column("sim_w_water_m_s");
  const auto& depth = log.column("m_depth");
  const auto& state = log.column("m_depth_state");
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < log.rows(); ++i) {
    if ((state[i] == 1.0 || state[i] == 2.0) && depth[i] > 2.0) {
      sum += w[i];
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

// The deepest depth with a CTD sample: where the water_density value is taken.
inline double deepest_ctd_depth(const flightlog::FlightLog& log) {
  const auto& depth = log.column("m_depth");
  const auto& cond = log.column("sci_water_cond");
  double deepest = 0.0;
  for (std::size_t i = 0; i < log.rows(); ++i) {
    if (std::isfinite(cond[i])) deepest = std::max(deepest, depth[i]);
  }
  return deepest;
}

}  // namespace glider::hidden
