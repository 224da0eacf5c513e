// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/observations.hpp"

#include <cmath>

#include "glider/flightlog/columns.hpp"
#include "glider/flightlog/gaps.hpp"
#include "glider/model/seawater.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

flightlog::Column filled_or_empty(const flightlog::FlightLog& log, const char* name, double max_age_s) {
  const flightlog::Column* column = log.find(name);
  if (column == nullptr) return flightlog::Column(log.rows(), NAN);
  return flightlog::forward_fill(log.time(), *column, max_age_s);
}

}  // namespace

Observations prepare_observations(const flightlog::FlightLog& log, const ObservationOptions& options) {
  const auto depth_source = flightlog::depth_series(log);
  if (!depth_source) {
    throw flightlog::FlightLogError(log.source(), 0, "m_depth", 0,
                                    "the log has no depth (m_depth or sci_water_pressure)");
  }
  const auto& time = log.time();
  const flightlog::Column depth = flightlog::interpolate_linear(time, depth_source->depth_m, 30.0);
  const flightlog::Column rate = log.has("m_depth_rate")
                                     ? flightlog::interpolate_linear(time, log.column("m_depth_rate"), 30.0)
                                     : flightlog::derive_depth_rate(time, depth, 30.0);
  const flightlog::Column pitch = filled_or_empty(log, "m_pitch", options.max_fill_age_s);
  const flightlog::Column ballast = filled_or_empty(log, "m_ballast_pumped", options.max_fill_age_s);
  const flightlog::Column battpos = filled_or_empty(log, "m_battpos", options.max_fill_age_s);
  const flightlog::Column temperature = filled_or_empty(log, "sci_water_temp", options.max_fill_age_s);
  const flightlog::Column conductivity = filled_or_empty(log, "sci_water_cond", options.max_fill_age_s);
  const flightlog::Column pressure = filled_or_empty(log, "sci_water_pressure", options.max_fill_age_s);
  const flightlog::Column logged_density = filled_or_empty(log, "sci_water_density", options.max_fill_age_s);
  const std::vector<flightlog::Phase> phases = flightlog::classify_phases(log);
  const auto segments = flightlog::find_segments(time, depth, phases);

  Observations obs;
  obs.has_battpos = log.has("m_battpos");
  int glide_number = -1;
  for (const flightlog::Segment& seg : segments) {
    if (seg.phase == flightlog::Phase::kInflection) obs.inflection_samples += seg.last - seg.first + 1;
    const bool dive = seg.phase == flightlog::Phase::kDive;
    if (!dive && seg.phase != flightlog::Phase::kClimb) continue;
    if (!(std::abs(seg.end_depth_m - seg.start_depth_m) >= 3.0)) continue;  // a bob, not a glide
    ++glide_number;
    ++obs.glides;
    for (std::size_t i = seg.first; i <= seg.last; ++i) {
      if (time[i] - seg.start_s < options.settle_s) continue;
      if (!(depth[i] >= options.min_depth_m) || !std::isfinite(rate[i]) || !std::isfinite(pitch[i]) ||
          !std::isfinite(ballast[i]) || std::abs(pitch[i]) < options.min_pitch_rad) {
        continue;
      }
      obs.time_s.push_back(time[i]);
      obs.depth_m.push_back(depth[i]);
      obs.depth_rate_m_s.push_back(rate[i]);
      obs.pitch_rad.push_back(pitch[i]);
      obs.ballast_cc.push_back(ballast[i]);
      obs.battpos_in.push_back(battpos[i]);
      obs.temperature_c.push_back(temperature[i]);
      const double rho =
          std::isfinite(logged_density[i])
              ? logged_density[i]
              : model::seawater::density_from_ctd(conductivity[i], temperature[i], bar_to_dbar(pressure[i]));
      obs.density_kg_m3.push_back(rho);
      obs.has_temperature |= std::isfinite(temperature[i]);
      obs.has_ctd |= std::isfinite(rho);
      obs.diving.push_back(dive);
      obs.yo.push_back(glide_number / 2);
    }
  }
  std::size_t dives = 0;
  for (bool d : obs.diving) dives += d ? 1 : 0;
  if (dives == 0) {
    throw flightlog::FlightLogError(log.source(), 0, "", 0,
                                    "no steady dives found (a dive must go 3 m or more down, below " +
                                        std::to_string(static_cast<int>(options.min_depth_m)) +
                                        " m, with pitch and ballast logged)");
  }
  obs.track = prepare_track(log, options.track);
  return obs;
}

}  // namespace glider::diagnose
