// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the model-discrepancy analysis works on: the log's steady glides as
// flat arrays, with the gaps filled by documented rules (flightlog/gaps.hpp).
#include <cstddef>
#include <vector>

#include "glider/diagnose/track.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"

namespace glider::diagnose {

struct Observations {
  // One entry per steady-glide sample used.
  std::vector<double> time_s, depth_m, depth_rate_m_s, pitch_rad, ballast_cc, battpos_in;
  std::vector<double> temperature_c;            // NaN where the log has none
  std::vector<double> density_kg_m3;            // TEOS-10 from the CTD; NaN where not available
  std::vector<double> speed_through_water_m_s;  // measured (a DVL's: never fitted, only scored); NaN where none
  std::vector<bool> diving;
  std::vector<int> yo;  // yo number (a dive and the climb after it)
  bool has_battpos = false, has_temperature = false, has_ctd = false;
  std::size_t glides = 0;              // dives + climbs found
  std::size_t inflection_samples = 0;  // samples in turns (not modelled by the steady model)
  Track track;                         // the whole log, for the dynamic model
  std::size_t size() const { return time_s.size(); }
};

struct ObservationOptions {
  double min_depth_m = 2.0;       // below the surface layer
  double min_pitch_rad = 0.1745;  // 10 deg: flatter is not a steady glide
  double settle_s = 30.0;         // skip the start of each glide (the pump and pitch settle)
  double max_fill_age_s = 60.0;   // forward fill of sparse columns
  // Fewer steady samples than this in dives or in climbs: "cannot judge" (a
  // 4 s decimated .sbd of one 20 m yo has ~25 of each).
  std::size_t min_samples_per_direction = 20;
  TrackOptions track;  // the whole log, for the dynamic model
};

// Throws flightlog::FlightLogError (file, line, column) when the log has no
// dives or lacks what the analysis needs, and "cannot judge" when it has too
// little to judge from: no climbs, too few samples, fewer than two yos.
Observations prepare_observations(const flightlog::FlightLog& log, const ObservationOptions& options = {});

}  // namespace glider::diagnose
