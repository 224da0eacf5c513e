// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/log_columns.hpp"

#include <cmath>

#include "glider/flightlog/columns.hpp"
#include "glider/flightlog/gaps.hpp"
#include "glider/model/seawater.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

flightlog::Column carried(const flightlog::FlightLog& log, const char* name, Fill fill, double max_age_s) {
  const flightlog::Column* column = log.find(name);
  if (column == nullptr) return flightlog::Column(log.rows(), NAN);
  return fill == Fill::kHold ? flightlog::forward_fill(log.time(), *column, max_age_s)
                             : flightlog::interpolate_linear(log.time(), *column, max_age_s);
}

}  // namespace

std::optional<LogColumns> read_log_columns(const flightlog::FlightLog& log, Fill fill, double fill_max_age_s,
                                           double depth_max_gap_s) {
  const auto depth_source = flightlog::depth_series(log);
  if (!depth_source) return std::nullopt;
  const auto& time = log.time();
  LogColumns c;
  c.depth_m = flightlog::interpolate_linear(time, depth_source->depth_m, depth_max_gap_s);
  c.pitch_rad = carried(log, "m_pitch", fill, fill_max_age_s);
  c.ballast_cc = carried(log, "m_ballast_pumped", fill, fill_max_age_s);
  c.battpos_in = carried(log, "m_battpos", fill, fill_max_age_s);
  c.temperature_c = carried(log, "sci_water_temp", fill, fill_max_age_s);
  const flightlog::Column conductivity = carried(log, "sci_water_cond", fill, fill_max_age_s);
  const flightlog::Column pressure = carried(log, "sci_water_pressure", fill, fill_max_age_s);
  const flightlog::Column logged_density = carried(log, "sci_water_density", fill, fill_max_age_s);
  c.density_kg_m3.resize(time.size());
  for (std::size_t i = 0; i < time.size(); ++i) {
    c.density_kg_m3[i] =
        std::isfinite(logged_density[i])
            ? logged_density[i]
            : model::seawater::density_from_ctd(conductivity[i], c.temperature_c[i], bar_to_dbar(pressure[i]));
  }
  c.has_battpos = log.has("m_battpos");
  c.phase = flightlog::classify_phases(log);
  c.segments = flightlog::find_segments(time, c.depth_m, c.phase);
  c.yo.assign(time.size(), -1);
  int current = -1;
  for (const flightlog::Segment& seg : c.segments) {
    if (seg.phase == flightlog::Phase::kDive && std::abs(seg.end_depth_m - seg.start_depth_m) >= kMinGlideExcursionM) {
      ++current;
    }
    for (std::size_t i = seg.first; i <= seg.last; ++i) c.yo[i] = current;
  }
  return c;
}

}  // namespace glider::diagnose
