// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/track.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <utility>

#include <Eigen/Dense>

#include "glider/diagnose/log_columns.hpp"
#include "glider/diagnose/stored_on_change.hpp"
#include "glider/flightlog/columns.hpp"
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

// The pitch the model flies, from the samples the log stored (a decimated
// .sbd stores m_pitch every few seconds and leaves the rows between empty):
// the stored samples smoothed by local_parabola_value among themselves, and
// between them the monotone cubic (PCHIP) through them, its value and slope
// at every row. A straight line between 4 s samples, smoothed and splined as
// if its rows were measurements, cuts a turn's corners (the model then flies
// a turn that starts late and ends early); on a log that stores every row
// this is the rule before, bit for bit.
struct PitchCurve {
  flightlog::Column value, slope;
};

PitchCurve stored_pitch_curve(std::span<const double> time, std::span<const double> stored, double half_window_s,
                              double max_gap_s) {
  const std::size_t n = time.size();
  std::vector<std::size_t> rows;
  std::vector<double> t, p;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(stored[i])) continue;
    rows.push_back(i);
    t.push_back(time[i]);
    p.push_back(stored[i]);
  }
  const flightlog::Column smooth = local_parabola_value(t, p, half_window_s, max_gap_s);
  const flightlog::Column slope = pchip_slopes(t, smooth, max_gap_s);
  PitchCurve curve{flightlog::Column(n, std::numeric_limits<double>::quiet_NaN()), flightlog::Column(n, 0.0)};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    curve.value[rows[k]] = smooth[k];
    curve.slope[rows[k]] = slope[k];
    if (k + 1 == rows.size() || rows[k + 1] == rows[k] + 1) continue;
    const double h = t[k + 1] - t[k];
    if (!(h > 0.0) || h > max_gap_s) continue;  // a gap: empty, as the reader's fill leaves it
    for (std::size_t i = rows[k] + 1; i < rows[k + 1]; ++i) {
      // The cubic Hermite of [k, k + 1] (run_flight.cpp's StagePitchTable flies the same form).
      const double f = (time[i] - t[k]) / h, f2 = f * f, f3 = f2 * f;
      curve.value[i] = (2.0 * f3 - 3.0 * f2 + 1.0) * smooth[k] + (f3 - 2.0 * f2 + f) * h * slope[k] +
                       (-2.0 * f3 + 3.0 * f2) * smooth[k + 1] + (f3 - f2) * h * slope[k + 1];
      curve.slope[i] = (6.0 * f2 - 6.0 * f) * (smooth[k] - smooth[k + 1]) / h + (3.0 * f2 - 4.0 * f + 1.0) * slope[k] +
                       (3.0 * f2 - 2.0 * f) * slope[k + 1];
    }
  }
  return curve;
}

// The ballast between the samples at which its value changed. A stored-on-
// change ballast (a decimated .sbd's m_ballast_pumped: every 4 s at most, and
// only when it moved; the reader holds it between) is a staircase on the
// rows: a stroke read as 4 s of hold and a jump, i.e. ~2 s late on average,
// which the model flies as pump lag and slower glides. Its measurements are
// the rows where a value first appears: the ramps (pump_ramps) are built on
// those alone, and every row gets the ramp's value at its time and the part
// of the ramp between it and the next row. A log that moves every row
// (pumping at 1 Hz) keeps its ramps; a constant stretch's repeats are no
// new measurements in either reading - but the last row at least one storing
// interval before a change is known to hold the old value (the writer would
// have stored the change by then): a knot too. Without it a stroke after a
// long hold whose own first row the log lost (a thinned full-rate log) was
// placed in the middle of the hold, minutes early (independent truth draw
// 2138946469: the model pumped mid-climb, held-out speed error x3.6).
void ramps_between_changes(Track& track) {
  const std::size_t n = track.size();
  auto changed_at = [&](std::size_t i) {
    return std::memcmp(&track.ballast_cc[i], &track.ballast_cc[i - 1], sizeof(double)) != 0;
  };
  // The storing interval: the shortest usual gap between consecutive changes
  // (a stroke stores at every chance), and half a row's spacing of jitter.
  flightlog::Column changes(n, std::numeric_limits<double>::quiet_NaN());
  std::vector<double> spacing;
  for (std::size_t run = 0; run < track.run_first.size(); ++run) {
    for (std::size_t i = track.run_first[run] + 1; i < track.run_end(run); ++i) {
      if (changed_at(i)) changes[i] = track.ballast_cc[i];
      spacing.push_back(track.time_s[i] - track.time_s[i - 1]);
    }
  }
  const double interval = storing_interval_s(track.time_s, changes);
  double jitter = 0.0;
  if (!spacing.empty()) {
    const auto middle = spacing.begin() + static_cast<long>(spacing.size() / 2);
    std::nth_element(spacing.begin(), middle, spacing.end());
    jitter = 0.5 * *middle;
  }
  std::vector<std::size_t> knot;  // rows: each run's first and last, where the value changes, and held before
  std::vector<std::size_t> knot_run_first;
  for (std::size_t run = 0; run < track.run_first.size(); ++run) {
    const std::size_t first = track.run_first[run], end = track.run_end(run);
    knot_run_first.push_back(knot.size());
    for (std::size_t i = first; i < end; ++i) {
      const bool change = i != first && changed_at(i);
      if (change && interval > 0.0) {
        std::size_t held = i - 1;
        while (held > knot.back() && track.time_s[held] > track.time_s[i] - interval + jitter) --held;
        if (held > knot.back()) knot.push_back(held);
      }
      if (i == first || i + 1 == end || change) knot.push_back(i);
    }
  }
  std::vector<double> kt, kv;
  for (std::size_t r : knot) {
    kt.push_back(track.time_s[r]);
    kv.push_back(track.ballast_cc[r]);
  }
  const std::vector<PumpRamp> ramps = pump_ramps(kt, kv, knot_run_first);
  track.ballast_ramp.assign(n, PumpRamp{});
  for (std::size_t k = 0; k + 1 < knot.size(); ++k) {
    const std::size_t a = knot[k], b = knot[k + 1];
    if (b == a + 1) {
      track.ballast_ramp[a] = ramps[k];
      continue;
    }
    if (std::find(knot_run_first.begin(), knot_run_first.end(), k + 1) != knot_run_first.end()) continue;
    const double span_s = kt[k + 1] - kt[k];
    const PumpRamp& ramp = ramps[k];
    auto fraction = [&](std::size_t i) { return (track.time_s[i] - kt[k]) / span_s; };
    for (std::size_t i = a + 1; i < b; ++i) track.ballast_cc[i] = ramp_value(kv[k], kv[k + 1], ramp, fraction(i));
    for (std::size_t i = a; i < b; ++i) {
      // Row i to i + 1 is [f0, f1] of the knots' interval: the ramp's corners
      // there, as fractions of the row's own interval.
      const double f0 = fraction(i), f1 = fraction(i + 1), width = f1 - f0;
      track.ballast_ramp[i] = {std::clamp((ramp.start - f0) / width, 0.0, 1.0),
                               std::clamp((ramp.end - f0) / width, 0.0, 1.0)};
    }
  }
}

}  // namespace

void read_as_stored(std::span<const double> time, std::span<const char> stored, std::span<double> depth,
                    double max_gap_s) {
  const std::size_t n = depth.size();
  std::size_t a = n;  // the last stored sample so far
  for (std::size_t i = 0; i < n; ++i) {
    if (!stored[i]) continue;
    if (a < n && i > a + 1 && time[i] - time[a] <= max_gap_s) {
      const double span_s = time[i] - time[a];
      for (std::size_t j = a + 1; j < i; ++j) depth[j] = std::lerp(depth[a], depth[i], (time[j] - time[a]) / span_s);
    }
    a = i;
  }
}

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
  const flightlog::Column* logged_pitch = log.find("m_pitch");
  const bool as_stored = options.as_stored && logged_pitch != nullptr;
  const PitchCurve pitch_curve =
      stored_pitch_curve(time, as_stored ? *logged_pitch : c.pitch_rad, options.pitch_half_window_s, gap);
  const flightlog::Column& pitch = pitch_curve.value;
  const flightlog::Column& pitch_slope = pitch_curve.slope;
  // Where the log stored the depth: the rows between hold the reader's line
  // between stored neighbours, and the model's depth is read the same way
  // (read_as_stored) before both go through the rate estimator.
  const auto logged_depth = flightlog::depth_series(log);
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
    track.depth_stored.push_back(!options.as_stored || std::isfinite(logged_depth->depth_m[i]) ? 1 : 0);
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
  if (options.as_stored) {
    ramps_between_changes(track);
  } else {
    track.ballast_ramp = pump_ramps(track.time_s, track.ballast_cc, track.run_first);
  }
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
