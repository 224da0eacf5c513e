// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/observations.hpp"

#include <cmath>
#include <set>
#include <string>

#include "glider/diagnose/log_columns.hpp"
#include "glider/flightlog/gaps.hpp"

namespace glider::diagnose {

namespace {

// What a diagnosis needs before it may name anything: steady dives AND climbs
// (a buoyancy offset and a drag change are told apart only by the two
// directions), enough samples in each, and two yos (one fitted, one held out).
// Below that the data cannot judge, and saying "none" or naming a cause would
// be a guess presented as a result.
void refuse_thin_data(const std::string& source, const Observations& obs, const ObservationOptions& options) {
  std::size_t dives = 0;
  std::set<int> yos_with_dives, yos_with_climbs;
  for (std::size_t i = 0; i < obs.size(); ++i) {
    dives += obs.diving[i] ? 1 : 0;
    (obs.diving[i] ? yos_with_dives : yos_with_climbs).insert(obs.yo[i]);
  }
  const std::size_t climbs = obs.size() - dives;
  const std::string where = "below " + std::to_string(static_cast<int>(options.min_depth_m)) +
                            " m, 3 m or more of depth, with pitch and ballast logged";
  if (dives == 0) throw flightlog::FlightLogError(source, 0, "", 0, "no steady dives found (" + where + ")");
  if (climbs == 0) {
    throw flightlog::FlightLogError(source, 0, "", 0,
                                    "cannot judge: no steady climbs found (" + where +
                                        "); dives alone cannot tell a buoyancy offset from a drag change");
  }
  const std::size_t need = options.min_samples_per_direction;
  if (dives < need || climbs < need) {
    throw flightlog::FlightLogError(
        source, 0, "", 0,
        "cannot judge: " + std::to_string(dives) + " steady-dive and " + std::to_string(climbs) +
            " steady-climb samples; the diagnosis needs at least " + std::to_string(need) + " of each");
  }
  std::set<int> yos = yos_with_dives;
  yos.insert(yos_with_climbs.begin(), yos_with_climbs.end());
  if (yos.size() < 2) {
    throw flightlog::FlightLogError(source, 0, "", 0,
                                    "cannot judge: steady glides in " + std::to_string(yos.size()) +
                                        " yo; the diagnosis fits alternate yos and scores the others on the yos "
                                        "it did not fit, so it needs at least two");
  }
}

}  // namespace

Observations prepare_observations(const flightlog::FlightLog& log, const ObservationOptions& options) {
  // The steady model takes one sample at a time: sparse columns hold their last value.
  const auto columns = read_log_columns(log, Fill::kHold, options.max_fill_age_s, 30.0);
  if (!columns) {
    throw flightlog::FlightLogError(log.source(), 0, "m_depth", 0,
                                    "the log has no depth (m_depth or sci_water_pressure)");
  }
  const LogColumns& c = *columns;
  const auto& time = log.time();
  const flightlog::Column rate = log.has("m_depth_rate")
                                     ? flightlog::interpolate_linear(time, log.column("m_depth_rate"), 30.0)
                                     : flightlog::derive_depth_rate(time, c.depth_m, 30.0);

  const flightlog::Column* logged_speed = log.find("sci_speed_through_water");
  const flightlog::Column speed = logged_speed != nullptr ? flightlog::interpolate_linear(time, *logged_speed, 5.0)
                                                          : flightlog::Column(time.size(), NAN);
  Observations obs;
  obs.has_battpos = c.has_battpos;
  for (const flightlog::Segment& seg : c.segments) {
    if (seg.phase == flightlog::Phase::kInflection) obs.inflection_samples += seg.last - seg.first + 1;
    const bool dive = seg.phase == flightlog::Phase::kDive;
    if (!dive && seg.phase != flightlog::Phase::kClimb) continue;
    if (!(std::abs(seg.end_depth_m - seg.start_depth_m) >= kMinGlideExcursionM)) continue;  // a bob, not a glide
    ++obs.glides;
    for (std::size_t i = seg.first; i <= seg.last; ++i) {
      if (time[i] - seg.start_s < options.settle_s) continue;
      if (!(c.depth_m[i] >= options.min_depth_m) || !std::isfinite(rate[i]) || !std::isfinite(c.pitch_rad[i]) ||
          !std::isfinite(c.ballast_cc[i]) || std::abs(c.pitch_rad[i]) < options.min_pitch_rad) {
        continue;
      }
      obs.time_s.push_back(time[i]);
      obs.depth_m.push_back(c.depth_m[i]);
      obs.depth_rate_m_s.push_back(rate[i]);
      obs.pitch_rad.push_back(c.pitch_rad[i]);
      obs.ballast_cc.push_back(c.ballast_cc[i]);
      obs.battpos_in.push_back(c.battpos_in[i]);
      obs.temperature_c.push_back(c.temperature_c[i]);
      obs.density_kg_m3.push_back(c.density_kg_m3[i]);
      obs.speed_through_water_m_s.push_back(speed[i]);
      obs.has_temperature |= std::isfinite(c.temperature_c[i]);
      obs.has_ctd |= std::isfinite(c.density_kg_m3[i]);
      obs.diving.push_back(dive);
      obs.yo.push_back(c.yo[i]);
    }
  }
  refuse_thin_data(log.source(), obs, options);
  obs.track = prepare_track(log, options.track);
  return obs;
}

}  // namespace glider::diagnose
