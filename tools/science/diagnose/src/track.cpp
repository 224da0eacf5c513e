// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/track.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include <Eigen/Dense>

#include "glider/diagnose/log_columns.hpp"
#include "glider/flightlog/gaps.hpp"

namespace glider::diagnose {
namespace {

// A straight line fitted to the samples within +-half_window_s of each
// sample (no gap longer than max_gap_s inside): its slope at the centre. For a smooth signal both are exact up to the
// curvature's (a parabola's slope is exact), and the sensor's noise is averaged down (1 Hz,
// +-5 s: ~10x less than a centred difference). Where the window holds no
// sample on one side, `fallback` is kept.
// The samples within +-half_window_s of sample i, with finite values and no
// gap longer than max_gap_s between neighbours: [lo, hi].
std::pair<std::size_t, std::size_t> window_around(std::span<const double> time, std::span<const double> values,
                                                  std::size_t i, double half_window_s, double max_gap_s) {
  std::size_t lo = i, hi = i;
  while (lo > 0 && time[i] - time[lo - 1] <= half_window_s && time[lo] - time[lo - 1] <= max_gap_s &&
         std::isfinite(values[lo - 1])) {
    --lo;
  }
  while (hi + 1 < time.size() && time[hi + 1] - time[i] <= half_window_s && time[hi + 1] - time[hi] <= max_gap_s &&
         std::isfinite(values[hi + 1])) {
    ++hi;
  }
  return {lo, hi};
}

// local_slope's value at sample i (finite), or nothing where the window has
// no sample on one side.
std::optional<double> slope_at(std::span<const double> time, std::span<const double> values, std::size_t i,
                               double half_window_s, double max_gap_s) {
  const auto [lo, hi] = window_around(time, values, i, half_window_s, max_gap_s);
  if (lo == i || hi == i) return std::nullopt;
  double st = 0.0, sv = 0.0;
  for (std::size_t j = lo; j <= hi; ++j) {
    st += time[j] - time[i];
    sv += values[j];
  }
  const double count = static_cast<double>(hi - lo + 1);
  const double mean_t = st / count, mean_v = sv / count;
  double stt = 0.0, stv = 0.0;
  for (std::size_t j = lo; j <= hi; ++j) {
    const double dt = time[j] - time[i] - mean_t;
    stt += dt * dt;
    stv += dt * (values[j] - mean_v);
  }
  if (!(stt > 0.0)) return std::nullopt;
  return stv / stt;
}

flightlog::Column local_slope(std::span<const double> time, std::span<const double> values, double half_window_s,
                              double max_gap_s, flightlog::Column fallback) {
  if (!(half_window_s > 0.0)) return fallback;
  const std::size_t n = time.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) continue;
    if (const auto slope = slope_at(time, values, i, half_window_s, max_gap_s)) fallback[i] = *slope;
  }
  return fallback;
}

// A parabola fitted to the samples within +-half_window_s of each sample
// (same window rule as local_slope), its value at the centre: noise is
// averaged down as by the line, but a turn's curvature is kept (the line
// cuts the corners of a pitch turn, which the model then flies).
flightlog::Column local_parabola_value(std::span<const double> time, std::span<const double> values,
                                       double half_window_s, double max_gap_s) {
  flightlog::Column out(values.begin(), values.end());
  if (!(half_window_s > 0.0)) return out;
  const std::size_t n = time.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(values[i])) continue;
    const auto [lo, hi] = window_around(time, values, i, half_window_s, max_gap_s);
    if (hi - lo < 3 || lo == i || hi == i) continue;  // a parabola needs more than three points to smooth
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (std::size_t j = lo; j <= hi; ++j) {
      const double dt = (time[j] - time[i]) / half_window_s;  // scaled: a well-conditioned system
      const Eigen::Vector3d basis(1.0, dt, dt * dt);
      normal += basis * basis.transpose();
      rhs += basis * values[j];
    }
    const Eigen::Vector3d coefficients = normal.ldlt().solve(rhs);
    if (std::isfinite(coefficients[0])) out[i] = coefficients[0];
  }
  return out;
}

// Slopes for a monotone cubic (PCHIP, Fritsch-Carlson) through the samples:
// the weighted harmonic mean of the neighbouring secants, zero at a local
// extremum, one-sided at gaps and ends. Between a Slocum's 2-5 s cycles a
// turn's pitch is a curve; straight lines between the samples cut its
// corners, which the model flies as a turn that starts late and ends early.
flightlog::Column pchip_slopes(std::span<const double> time, std::span<const double> values, double max_gap_s) {
  const std::size_t n = time.size();
  flightlog::Column slope(n, 0.0);
  auto secant = [&](std::size_t a) -> std::optional<std::pair<double, double>> {  // (h, d) of [a, a + 1]
    if (a + 1 >= n) return std::nullopt;
    const double h = time[a + 1] - time[a];
    if (!(h > 0.0) || h > max_gap_s || !std::isfinite(values[a]) || !std::isfinite(values[a + 1])) return std::nullopt;
    return std::make_pair(h, (values[a + 1] - values[a]) / h);
  };
  for (std::size_t i = 0; i < n; ++i) {
    const auto before = i > 0 ? secant(i - 1) : std::nullopt;
    const auto after = secant(i);
    if (before && after) {
      const auto [h0, d0] = *before;
      const auto [h1, d1] = *after;
      if (d0 * d1 > 0.0) {
        const double w0 = 2.0 * h1 + h0, w1 = h1 + 2.0 * h0;
        slope[i] = (w0 + w1) / (w0 / d0 + w1 / d1);
      }
    } else if (before) {
      slope[i] = before->second;
    } else if (after) {
      slope[i] = after->second;
    }
  }
  return slope;
}

}  // namespace

flightlog::Column depth_rate_estimate(std::span<const double> time, std::span<const double> depth, double half_window_s,
                                      double max_gap_s) {
  return local_slope(time, depth, half_window_s, max_gap_s, flightlog::derive_depth_rate(time, depth, max_gap_s));
}

double depth_rate_estimate_at(std::span<const double> time, std::span<const double> depth, std::size_t i,
                              double half_window_s, double max_gap_s) {
  if (half_window_s > 0.0) {
    if (const auto slope = slope_at(time, depth, i, half_window_s, max_gap_s)) return *slope;
  }
  // flightlog::derive_depth_rate's centred difference, every neighbour finite.
  const std::size_t first = i > 0 && time[i] - time[i - 1] <= max_gap_s ? i - 1 : i;
  const std::size_t last = i + 1 < time.size() && time[i + 1] - time[i] <= max_gap_s ? i + 1 : i;
  if (first == last) return std::numeric_limits<double>::quiet_NaN();
  return (depth[last] - depth[first]) / (time[last] - time[first]);
}

Track prepare_track(const flightlog::FlightLog& log, const TrackOptions& options) {
  Track track;
  const double gap = options.max_gap_s;
  const auto columns = read_log_columns(log, Fill::kInterpolate, gap, gap);
  if (!columns) return track;
  const LogColumns& c = *columns;
  const auto& time = log.time();
  const flightlog::Column& depth = c.depth_m;
  // The measured depth rate: a centred slope of the depth, not Slocum's
  // m_depth_rate, which differences backwards (it trails by half a cycle,
  // ~2 s, which the fit would read as a pump lag).
  const flightlog::Column rate = depth_rate_estimate(time, depth, options.rate_half_window_s, gap);
  track.rate_half_window_s = options.rate_half_window_s;
  track.max_gap_s = gap;
  track.spin_up_s = options.spin_up_s;
  // The pitch is the model's input: its sensor noise (and wave-driven
  // wobble) would add angle of attack, i.e. drag, that the glider never had.
  const flightlog::Column pitch = local_parabola_value(time, c.pitch_rad, options.pitch_half_window_s, gap);
  const flightlog::Column pitch_slope = pchip_slopes(time, pitch, gap);
  const flightlog::Column* logged_speed = log.find("sci_speed_through_water");
  const flightlog::Column speed = logged_speed != nullptr ? flightlog::interpolate_linear(time, *logged_speed, 5.0)
                                                          : flightlog::Column(time.size(), NAN);
  const std::vector<flightlog::Phase>& phases = c.phase;
  const std::vector<int>& yo = c.yo;

  double run_start_s = 0.0;
  bool in_run = false;
  for (std::size_t i = 0; i < time.size(); ++i) {
    const bool usable =
        depth[i] >= options.run_min_depth_m && std::isfinite(pitch[i]) && std::isfinite(c.ballast_cc[i]);
    if (!usable) {
      in_run = false;
      continue;
    }
    if (!in_run || time[i] - track.time_s.back() > gap) {
      track.run_first.push_back(track.size());
      run_start_s = time[i];
      in_run = true;
    }
    const std::size_t k = track.size();
    track.time_s.push_back(time[i]);
    track.depth_m.push_back(depth[i]);
    track.depth_rate_m_s.push_back(rate[i]);
    track.pitch_rad.push_back(pitch[i]);
    track.pitch_slope_rad_s.push_back(pitch_slope[i]);
    track.ballast_cc.push_back(c.ballast_cc[i]);
    track.battpos_in.push_back(c.battpos_in[i]);
    track.temperature_c.push_back(c.temperature_c[i]);
    track.density_kg_m3.push_back(c.density_kg_m3[i]);
    track.speed_through_water_m_s.push_back(speed[i]);
    track.phase.push_back(phases[i]);
    track.yo.push_back(yo[i]);
    const bool moving = phases[i] == flightlog::Phase::kDive || phases[i] == flightlog::Phase::kClimb ||
                        phases[i] == flightlog::Phase::kInflection;
    if (moving && yo[i] >= 0 && depth[i] >= options.min_depth_m && std::isfinite(rate[i]) &&
        time[i] - run_start_s >= options.spin_up_s) {
      track.scored.push_back(k);
    }
  }
  track.ballast_ramp = pump_ramps(track.time_s, track.ballast_cc, track.run_first);
  std::vector<double> temperatures;
  for (double t : track.temperature_c) {
    if (std::isfinite(t)) temperatures.push_back(t);
  }
  track.median_temperature_c = NAN;
  if (!temperatures.empty()) {
    const auto middle = temperatures.begin() + static_cast<long>(temperatures.size() / 2);
    std::nth_element(temperatures.begin(), middle, temperatures.end());
    track.median_temperature_c = *middle;
  }
  return track;
}

}  // namespace glider::diagnose
