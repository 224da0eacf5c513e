// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_track.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "glider/diagnose/log_columns.hpp"
#include "glider/diagnose/stored_on_change.hpp"
#include "glider/diagnose/track.hpp"
#include "glider/flightlog/gaps.hpp"
#include "glider/model/hydrodynamics.hpp"
#include "glider/model/steady_glide.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double wrap_pi(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

flightlog::Column required(const flightlog::FlightLog& log, const char* name, const char* what) {
  const flightlog::Column* c = log.find(name);
  if (c == nullptr || log.fill_fraction(name) == 0.0) {
    throw HeadingUnavailable(log.source() + ": no " + name + " column with values (" + what +
                             "): the heading plane is not diagnosed");
  }
  return *c;
}

double median(std::vector<double> x) {
  if (x.empty()) return kNaN;
  std::nth_element(x.begin(), x.begin() + static_cast<long>(x.size() / 2), x.end());
  return x[x.size() / 2];
}

// Speed through the water and lift factor of the steady glide at the logged
// pitch: the angle of attack follows from the pitch alone (the force
// balance's tan(path) = C_D / C_L), the buoyancy only scales the speed,
// which the measured depth rate gives.
struct GlideKinematics {
  double speed_m_s = kNaN, lift_factor = kNaN;
};

GlideKinematics kinematics(const model::PitchGlideSolver& solver, const model::Hydrodynamics& hydro, double density,
                           double pitch_rad, double depth_rate_m_s) {
  const auto glide = solver.solve(density, pitch_rad, pitch_rad < 0.0 ? 1.0 : -1.0);
  if (!glide.glide || !std::isfinite(depth_rate_m_s)) return {};
  const double sin_path = std::abs(std::sin(glide.glide->glide_path_rad));
  if (sin_path < 0.05) return {};
  GlideKinematics k;
  k.speed_m_s = std::abs(depth_rate_m_s) / sin_path;
  // The dynamics' effective angle of attack (dynamics.cpp): the lift over the
  // whole lift slope, hull AND wings. The hull's slope alone (as here until
  // the independent-truth benchmark found it) made a winged glider's roll turn
  // it twice as hard as the model flies it, and the fit paid with a spurious
  // roll_offset of ~0.09 rad on 150 of 160 winged truth logs.
  const double slope = model::lift_slope_per_rad(hydro);
  k.lift_factor = slope != 0.0 ? model::force_coefficients(hydro, glide.glide->alpha_rad).lift / slope : 0.0;
  return k;
}

}  // namespace

std::optional<double> logged_setting(const flightlog::FlightLog& log, std::string_view name) {
  // The key may carry a note: "settings_at_file_open (first dbd cycle)".
  const std::string key = std::string(name) + "=";
  for (const flightlog::MetadataEntry& entry : log.metadata()) {
    if (entry.key.rfind("settings_at_file_open", 0) != 0) continue;
    std::istringstream in(entry.value);
    std::string item;
    while (in >> item) {
      if (item.rfind(key, 0) != 0) continue;
      try {
        return std::stod(item.substr(key.size()));
      } catch (const std::exception&) {
        return std::nullopt;  // a malformed setting is treated as not stated
      }
    }
  }
  return std::nullopt;
}

HeadingTrack prepare_heading_track(const flightlog::FlightLog& log, const model::VehicleParams& vehicle,
                                   const HeadingTrackOptions& options) {
  const flightlog::Column heading = required(log, "m_heading", "the measured heading");
  const flightlog::Column command = required(log, "c_heading", "the heading command");
  const flightlog::Column fin = required(log, "m_fin", "the measured fin angle");
  const flightlog::Column fin_command = required(log, "c_fin", "the fin command");
  const double gap = options.max_gap_s;
  const auto columns = read_log_columns(log, Fill::kInterpolate, gap, gap);
  if (!columns) throw HeadingUnavailable(log.source() + ": no depth: the heading plane is not diagnosed");
  const LogColumns& c = *columns;
  const auto& time = log.time();

  HeadingTrack t;
  t.rate_half_window_s = options.rate_half_window_s;
  t.max_gap_s = gap;
  t.yaw_fast_pole_max_s = options.yaw_fast_pole_max_s < 0.0 ? 0.5 * std::abs(vehicle.heading.yaw_time_constant_s)
                                                            : options.yaw_fast_pole_max_s;
  if (!std::isfinite(t.yaw_fast_pole_max_s)) t.yaw_fast_pole_max_s = 0.0;
  t.yaw_fast_pole_s = 0.5 * t.yaw_fast_pole_max_s;
  // Times from the log's start: a delay's numerical derivative (steps of
  // 1e-8 s) would vanish in the rounding of Unix times (1e9 s).
  const double t0 = time.empty() ? 0.0 : time.front();
  for (double x : time) t.row_time_s.push_back(x - t0);
  t.row_heading_rad = heading;
  t.row_command_rad = command;
  t.row_fin_rad = fin;
  // A decimated file stores the fin when it moved: held where the writer
  // found it unchanged, a straight line where it moved (stored_on_change.hpp).
  t.row_fin_filled_rad = options.fin_stored_on_change ? fill_stored_on_change(time, fin, gap)
                                                      : flightlog::interpolate_linear(time, fin, gap);
  t.row_fin_command_rad = fin_command;
  t.row_depth_m = c.depth_m;
  t.row_yo = c.yo;
  const flightlog::Column* state = log.find("m_depth_state");
  const flightlog::Column state_held =
      state != nullptr ? flightlog::forward_fill(time, *state, gap) : flightlog::Column(time.size(), kNaN);
  for (std::size_t k = 0; k < time.size(); ++k) {
    const bool by_phase =
        (c.phase[k] == flightlog::Phase::kDive || c.phase[k] == flightlog::Phase::kClimb) && c.depth_m[k] >= 1.0;
    t.row_gliding.push_back(state != nullptr ? (state_held[k] == 1.0 || state_held[k] == 2.0) : by_phase);
  }
  t.fin_max_rad = logged_setting(log, "f_fin_safety_max").value_or(vehicle.heading.fin_max_rad);

  const flightlog::Column* roll_column = log.find("m_roll");
  t.roll_logged = roll_column != nullptr && log.fill_fraction("m_roll") > 0.0;
  const flightlog::Column roll =
      t.roll_logged ? flightlog::interpolate_linear(time, *roll_column, gap) : flightlog::Column(time.size(), kNaN);
  // On the shorter arc: a linear fill across north swung through south (issue 24's
  // health found fin effectiveness -17 on decimated .sbd from it).
  const flightlog::Column heading_filled = flightlog::interpolate_angle_rad(time, heading, gap);
  const flightlog::Column depth_rate = depth_rate_estimate(time, c.depth_m, options.rate_half_window_s, gap);
  const model::PitchGlideSolver solver(vehicle.hydro);

  // Runs: steady glide rows under a heading command, split at phase changes and gaps.
  std::vector<double> all_rolls;
  std::size_t i = 0;
  while (i < time.size()) {
    auto usable = [&](std::size_t k) {
      return (c.phase[k] == flightlog::Phase::kDive || c.phase[k] == flightlog::Phase::kClimb) &&
             c.depth_m[k] >= options.min_depth_m && std::abs(c.pitch_rad[k]) >= options.min_pitch_rad &&
             std::isfinite(command[k]) && std::isfinite(heading_filled[k]) && std::isfinite(t.row_fin_filled_rad[k]);
    };
    if (!usable(i)) {
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    while (end < time.size() && usable(end) && c.phase[end] == c.phase[i] && time[end] - time[end - 1] <= gap) ++end;
    std::vector<std::size_t> rows;
    for (std::size_t k = i; k < end; ++k) {
      const GlideKinematics g =
          kinematics(solver, vehicle.hydro, vehicle.trim_density_kg_m3, c.pitch_rad[k], depth_rate[k]);
      if (std::isfinite(g.speed_m_s)) rows.push_back(k);
    }
    if (rows.size() >= 5 && time[rows.back()] - time[rows.front()] >= options.min_run_s) {
      const std::size_t first = t.size();
      t.run_first.push_back(first);
      std::vector<double> run_roll;
      for (std::size_t k : rows) {
        if (std::isfinite(roll[k])) run_roll.push_back(roll[k]);
      }
      const double roll_here = run_roll.empty() ? vehicle.heading.roll_offset_rad : median(run_roll);
      all_rolls.insert(all_rolls.end(), run_roll.begin(), run_roll.end());
      double unwrapped = heading_filled[rows.front()];
      for (std::size_t n = 0; n < rows.size(); ++n) {
        const std::size_t k = rows[n];
        if (n > 0) unwrapped += wrap_pi(heading_filled[k] - heading_filled[rows[n - 1]]);
        const GlideKinematics g =
            kinematics(solver, vehicle.hydro, vehicle.trim_density_kg_m3, c.pitch_rad[k], depth_rate[k]);
        t.time_s.push_back(time[k] - t0);
        t.heading_rad.push_back(unwrapped);
        t.speed_m_s.push_back(g.speed_m_s);
        t.depth_m.push_back(c.depth_m[k]);
        t.depth_rate_m_s.push_back(depth_rate[k]);
        t.lift_factor.push_back(g.lift_factor);
        t.roll_rad.push_back(roll_here);
        t.roll_sample_rad.push_back(std::isfinite(roll[k]) ? roll[k] : roll_here);
        t.phase.push_back(c.phase[k]);
        t.yo.push_back(c.yo[k]);
        if (time[k] - time[rows.front()] >= options.settle_s) t.scored.push_back(t.size() - 1);
      }
      const std::span<const double> run_time(t.time_s.data() + first, t.size() - first);
      const std::span<const double> run_heading(t.heading_rad.data() + first, t.size() - first);
      const flightlog::Column rate = depth_rate_estimate(run_time, run_heading, options.rate_half_window_s, gap);
      t.yaw_rate_rad_s.insert(t.yaw_rate_rad_s.end(), rate.begin(), rate.end());
    }
    i = end;
  }
  if (t.scored.empty()) {
    throw HeadingUnavailable(log.source() +
                             ": no steady glide under a heading command (c_heading) with m_heading and m_fin: the "
                             "heading plane is not diagnosed");
  }
  t.median_roll_rad = all_rolls.empty() ? vehicle.heading.roll_offset_rad : median(all_rolls);
  return t;
}

}  // namespace glider::diagnose
