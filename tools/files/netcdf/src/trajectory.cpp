// SPDX-License-Identifier: Apache-2.0
#include "glider/netcdf/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glider/flightlog/columns.hpp"
#include "glider/model/seawater.hpp"
#include "glider/slocum/lat_lon.hpp"

namespace glider::netcdf {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
constexpr double kMaxJoinGapS = 600.0;  // a dive or climb of a shelf glider lasts 2-10 min

std::vector<double> column_or_nan(const flightlog::FlightLog& log, std::string_view name, double scale = 1.0) {
  std::vector<double> out(log.rows(), kNaN);
  if (const flightlog::Column* column = log.find(name)) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = (*column)[i] * scale;
  }
  return out;
}

std::vector<double> decimal_degrees(const flightlog::FlightLog& log, std::string_view name) {
  std::vector<double> out(log.rows(), kNaN);
  if (const flightlog::Column* column = log.find(name)) {
    for (std::size_t i = 0; i < out.size(); ++i) {
      const double v = (*column)[i];
      if (std::isfinite(v) && slocum::is_valid_nmea(name, v)) out[i] = slocum::nmea_to_decimal(v);
    }
  }
  return out;
}

double median_interval(const std::vector<double>& time) {
  if (time.size() < 2) return 0.0;
  std::vector<double> dt(time.size() - 1);
  for (std::size_t i = 1; i < time.size(); ++i) dt[i - 1] = time[i] - time[i - 1];
  std::nth_element(dt.begin(), dt.begin() + static_cast<long>(dt.size() / 2), dt.end());
  return dt[dt.size() / 2];
}

bool is_glide(flightlog::Phase p) { return p == flightlog::Phase::kDive || p == flightlog::Phase::kClimb; }

// Dives and climbs as profiles: consecutive segments of the same direction
// joined across short turns or unknown stretches (a slow sample, a short gap),
// split at the surface or at the other direction; a profile must span
// min_depth_change_m.
void number_profiles(Trajectory& t, const std::vector<flightlog::Segment>& segments, double join_s,
                     double min_depth_change_m) {
  t.profile.assign(t.size(), 0);
  struct Group {
    flightlog::Phase phase = flightlog::Phase::kUnknown;
    std::size_t first = 0, last = 0;
    bool open = false;
  } group;
  auto close = [&] {
    if (!group.open) return;
    group.open = false;
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = group.first; i <= group.last; ++i) {
      if (std::isfinite(t.depth_m[i])) {
        lo = std::min(lo, t.depth_m[i]);
        hi = std::max(hi, t.depth_m[i]);
      }
    }
    if (!(hi - lo >= min_depth_change_m)) return;
    const auto number = static_cast<std::int32_t>(++t.profiles);
    for (std::size_t i = group.first; i <= group.last; ++i) t.profile[i] = number;
  };
  for (const flightlog::Segment& s : segments) {
    if (is_glide(s.phase)) {
      // Across a short break, or a longer gap in the data (up to kMaxJoinGapS)
      // when the depth went on the same way: a hole in a dive is not two dives.
      const double gap_s = s.start_s - t.time_s[group.last];
      const double went = t.depth_m[s.first] - t.depth_m[group.last];
      const bool same_way = s.phase == flightlog::Phase::kDive ? went > 0.0 : went < 0.0;
      const bool joins =
          group.open && group.phase == s.phase && (gap_s <= join_s || (gap_s <= kMaxJoinGapS && same_way));
      if (!joins) {
        close();
        group = {s.phase, s.first, s.last, true};
      }
      group.last = s.last;
    } else if (s.phase == flightlog::Phase::kSurface ||
               (s.phase == flightlog::Phase::kInflection && s.end_s - s.start_s > join_s)) {
      close();
    }
  }
  close();
}

}  // namespace

std::vector<double> forward_fill(const std::vector<double>& time, const flightlog::Column& values, double max_age_s) {
  std::vector<double> out(values.size(), kNaN);
  double last = kNaN, last_t = -INFINITY;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i])) {
      last = values[i];
      last_t = time[i];
    }
    if (time[i] - last_t <= max_age_s) out[i] = last;
  }
  return out;
}

std::vector<double> interpolate(const std::vector<double>& time, const std::vector<double>& values, double max_gap_s) {
  std::vector<double> out(values.size(), kNaN);
  std::size_t previous = values.size();  // index of the last finite value
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i])) continue;
    out[i] = values[i];
    if (previous < values.size() && i > previous + 1 && time[i] - time[previous] <= max_gap_s) {
      const double span = time[i] - time[previous];
      for (std::size_t k = previous + 1; k < i; ++k) {
        const double f = (time[k] - time[previous]) / span;
        out[k] = values[previous] + f * (values[i] - values[previous]);
      }
    }
    previous = i;
  }
  return out;
}

std::int8_t og_phase_code(flightlog::Phase phase) {
  switch (phase) {
    case flightlog::Phase::kClimb:
      return 1;  // ascent
    case flightlog::Phase::kDive:
      return 2;  // descent
    case flightlog::Phase::kSurface:
      return 3;  // surfacing
    case flightlog::Phase::kInflection:
      return 5;  // inflexion
    case flightlog::Phase::kUnknown:
      break;
  }
  return 0;  // unknown
}

Trajectory make_trajectory(const flightlog::FlightLog& log, const ProfileOptions& options) {
  Trajectory t;
  t.time_s = log.time();
  const auto depth = flightlog::depth_series(log);
  if (!depth) {
    throw flightlog::FlightLogError(log.source(), 0, "m_depth", 0, "no depth: neither m_depth nor sci_water_pressure");
  }
  t.depth_m = depth->depth_m;
  t.depth_source = depth->source;
  t.pressure_dbar = column_or_nan(log, "sci_water_pressure", 10.0);
  t.temperature_c = column_or_nan(log, "sci_water_temp");
  t.conductivity_s_m = column_or_nan(log, "sci_water_cond");
  t.salinity.assign(t.size(), kNaN);
  t.density_kg_m3.assign(t.size(), kNaN);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double c = t.conductivity_s_m[i], temp = t.temperature_c[i], p = t.pressure_dbar[i];
    if (!(c > 0.0) || !std::isfinite(temp) || !std::isfinite(p)) continue;  // the CTD's P=T=C=0 records are no water
    t.salinity[i] = model::seawater::practical_salinity(c, temp, std::max(p, 0.0));
    t.density_kg_m3[i] = model::seawater::density_from_ctd(c, temp, std::max(p, 0.0));
  }
  t.dr_latitude = decimal_degrees(log, "m_lat");
  t.dr_longitude = decimal_degrees(log, "m_lon");
  t.gps_latitude = decimal_degrees(log, "m_gps_lat");
  t.gps_longitude = decimal_degrees(log, "m_gps_lon");
  // The log repeats the last fix in the cycles after it ("same value"
  // records), also while the glider already dives: only a new position is a fix.
  double last_lat = kNaN, last_lon = kNaN;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t.gps_latitude[i]) || !std::isfinite(t.gps_longitude[i])) {
      t.gps_latitude[i] = t.gps_longitude[i] = kNaN;
      continue;
    }
    const bool repeat = t.gps_latitude[i] == last_lat && t.gps_longitude[i] == last_lon;
    last_lat = t.gps_latitude[i];
    last_lon = t.gps_longitude[i];
    if (repeat) t.gps_latitude[i] = t.gps_longitude[i] = kNaN;
  }
  // Every sample's position: the glider's own dead reckoning (which restarts
  // from each GPS fix), linearly in time between its logged values.
  const double unbounded = INFINITY;
  t.latitude = interpolate(t.time_s, t.dr_latitude, unbounded);
  t.longitude = interpolate(t.time_s, t.dr_longitude, unbounded);
  t.heading_deg = column_or_nan(log, "m_heading", kRadToDeg);
  t.pitch_deg = column_or_nan(log, "m_pitch", kRadToDeg);
  t.roll_deg = column_or_nan(log, "m_roll", kRadToDeg);
  const double fill_age_s = 60.0;  // the diagnosis's forward fill of sparse columns
  t.pitch_rad = log.has("m_pitch") ? forward_fill(t.time_s, log.column("m_pitch"), fill_age_s)
                                   : std::vector<double>(t.size(), kNaN);
  const char* ballast = log.has("m_ballast_pumped") ? "m_ballast_pumped" : "m_de_oil_vol";
  t.ballast_cc =
      log.has(ballast) ? forward_fill(t.time_s, log.column(ballast), fill_age_s) : std::vector<double>(t.size(), kNaN);
  t.pumped_cc = column_or_nan(log, ballast);

  flightlog::PhaseOptions phase_options;
  const double dt = median_interval(t.time_s);
  phase_options.max_gap_s = std::max(options.max_gap_s, 3.0 * dt);
  phase_options.bridge_s = std::max(phase_options.bridge_s, 3.0 * dt);
  t.phase = flightlog::classify_phases(log, phase_options);
  const auto segments = flightlog::find_segments(t.time_s, t.depth_m, t.phase);
  number_profiles(t, segments, std::max(60.0, 2.0 * phase_options.max_gap_s), options.min_depth_change_m);
  return t;
}

}  // namespace glider::netcdf
