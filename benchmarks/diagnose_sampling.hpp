// SPDX-License-Identifier: Apache-2.0
#pragma once
// bench_diagnose_coverage's sampling experiment: where does the error of a
// diagnosis on a thinned log come from? One 1 Hz flight is diagnosed as flown,
// with its rows thinned like a Slocum log's (2-5 s apart), or at 1 Hz with
// only one input (pitch, ballast, battery) replaced by what the diagnosis
// reconstructs of it from the thinned rows: a paired comparison that names the
// input whose reconstruction biases the fit.
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "glider/diagnose/observations.hpp"
#include "glider/diagnose/track.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/gaps.hpp"
#include "hidden_truth.hpp"

namespace glider::hidden {

// slocum: the SIL writer thins the rows (the benchmark's default). The others
// fly at 1 Hz: 1hz as flown; rows: the rows thinned afterwards (the same
// flight as 1hz); pitch / ballast / battpos: every row kept, that one input
// replaced by its reconstruction from the thinned rows.
enum class Sampling { kSlocum, k1Hz, kRows, kPitch, kBallast, kBattpos };

inline Sampling sampling_from(const std::string& name) {
  if (name == "slocum") return Sampling::kSlocum;
  if (name == "1hz") return Sampling::k1Hz;
  if (name == "rows") return Sampling::kRows;
  if (name == "pitch") return Sampling::kPitch;
  if (name == "ballast") return Sampling::kBallast;
  if (name == "battpos") return Sampling::kBattpos;
  throw std::invalid_argument("unknown sampling '" + name + "'");
}

// The rows a Slocum log would keep: the first, then each next one U(2, 5) s
// after the last kept (the SIL writer's LogGaps rule, its surface gaps aside:
// the diagnosis never scores the surface).
inline std::vector<bool> slocum_rows(const flightlog::Column& time, std::uint64_t seed) {
  std::mt19937_64 rng(seed ^ 0x5eed5a3b1e5ULL);
  std::vector<bool> keep(time.size(), false);
  double next_s = -1e300;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] + 1e-9 < next_s) continue;
    keep[i] = true;
    next_s = time[i] + uniform(rng, 2.0, 5.0);
  }
  return keep;
}

inline flightlog::FlightLog with_columns(const flightlog::FlightLog& log, std::vector<flightlog::Column> columns) {
  std::size_t time_index = 0;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (&log.column(log.column_names()[c]) == &log.time()) time_index = c;
  }
  return {log.source(), log.metadata(), log.column_names(), std::move(columns), time_index};
}

inline flightlog::FlightLog keep_rows(const flightlog::FlightLog& log, const std::vector<bool>& keep) {
  std::vector<flightlog::Column> columns;
  for (const std::string& name : log.column_names()) {
    const flightlog::Column& all = log.column(name);
    flightlog::Column kept;
    for (std::size_t i = 0; i < all.size(); ++i) {
      if (keep[i]) kept.push_back(all[i]);
    }
    columns.push_back(std::move(kept));
  }
  return with_columns(log, std::move(columns));
}

// The pitch the dynamic model flies on the thinned rows (DynamicFlightModel:
// the cubic Hermite through the track's smoothed pitch and its PCHIP slopes),
// at every 1 Hz time inside one of the thinned track's runs; the logged pitch
// elsewhere.
inline flightlog::Column reconstructed_pitch(const flightlog::Column& time, const flightlog::Column& logged,
                                             const diagnose::Track& thinned) {
  flightlog::Column out = logged;
  for (std::size_t run = 0; run < thinned.run_first.size(); ++run) {
    const std::size_t first = thinned.run_first[run], end = thinned.run_end(run);
    std::size_t i = first;
    for (std::size_t r = 0; r < time.size(); ++r) {
      if (time[r] < thinned.time_s[first] || time[r] > thinned.time_s[end - 1]) continue;
      while (i + 2 < end && thinned.time_s[i + 1] < time[r]) ++i;
      const std::size_t j = i + 1 < end ? i + 1 : i;
      const double dt = thinned.time_s[j] - thinned.time_s[i];
      const double f = dt > 0.0 ? (time[r] - thinned.time_s[i]) / dt : 0.0;
      const double f2 = f * f, f3 = f2 * f;
      out[r] = (2.0 * f3 - 3.0 * f2 + 1.0) * thinned.pitch_rad[i] +
               (f3 - 2.0 * f2 + f) * dt * thinned.pitch_slope_rad_s[i] + (-2.0 * f3 + 3.0 * f2) * thinned.pitch_rad[j] +
               (f3 - f2) * dt * thinned.pitch_slope_rad_s[j];
    }
  }
  return out;
}

// A 1 Hz log with its thinned form's reconstruction of one input (see
// Sampling), or the thinned rows themselves.
inline flightlog::FlightLog resampled(const flightlog::FlightLog& log, Sampling sampling, std::uint64_t seed) {
  if (sampling == Sampling::kSlocum || sampling == Sampling::k1Hz) return log;
  const std::vector<bool> keep = slocum_rows(log.time(), seed);
  const flightlog::FlightLog thinned = keep_rows(log, keep);
  if (sampling == Sampling::kRows) return thinned;
  const char* input = sampling == Sampling::kPitch     ? "m_pitch"
                      : sampling == Sampling::kBallast ? "m_ballast_pumped"
                                                       : "m_battpos";
  std::vector<flightlog::Column> columns;
  for (const std::string& name : log.column_names()) {
    flightlog::Column column = log.column(name);
    if (name == input && sampling == Sampling::kPitch) {
      column = reconstructed_pitch(log.time(), column, diagnose::prepare_observations(thinned).track);
    } else if (name == input) {  // the model interpolates these linearly between samples
      for (std::size_t i = 0; i < column.size(); ++i) {
        if (!keep[i]) column[i] = NAN;
      }
      column = flightlog::interpolate_linear(log.time(), column, 30.0);
    }
    columns.push_back(std::move(column));
  }
  return with_columns(log, std::move(columns));
}

}  // namespace glider::hidden
