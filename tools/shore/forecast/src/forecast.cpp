// SPDX-License-Identifier: Apache-2.0
#include "glider/forecast/forecast.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "glider/cli/tool.hpp"
#include "glider/config/value_limits.hpp"
#include "glider/firmware/geo.hpp"
#include "glider/forecast/speed_term.hpp"
#include "glider/forecast/tidal_prior.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/portable_random.hpp"

namespace glider::forecast {
namespace fs = std::filesystem;

void write_atomically(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  const fs::path temp = path.parent_path() / ("." + path.filename().string() + ".tmp");
  {
    std::ofstream out(temp, std::ios::out | std::ios::trunc);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(temp.string() + ": cannot write");
  }
  fs::rename(temp, path);
}

namespace {

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double at = p * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

// The vehicle the glider flies: --vehicle, else health's current estimate,
// else the file boards/gliders.toml gives for the glider.
fs::path vehicle_file(const fs::path& glider_dir, const std::string& glider, const ForecastOptions& o,
                      std::string& source) {
  if (!o.vehicle.empty()) {
    source = o.vehicle;
    return o.vehicle;
  }
  if (fs::is_regular_file(glider_dir / "health" / "vehicle.toml")) {
    source = (glider_dir / "health" / "vehicle.toml").string() + " (health's current estimates)";
    return glider_dir / "health" / "vehicle.toml";
  }
  // The pilot's own file for this glider, as health reads it (tools/shore/health glider_dir): before any
  // health estimate exists (a glider's first calls) the forecast flies it too.
  if (fs::is_regular_file(glider_dir / "vehicle.toml")) {
    source = (glider_dir / "vehicle.toml").string() + " (the glider's vehicle file)";
    return glider_dir / "vehicle.toml";
  }
  const fs::path boards = o.boards_dir.empty() ? fs::path(cli::boards_dir()) : fs::path(o.boards_dir);
  const fs::path index = boards / "gliders.toml";
  try {
    const toml::table table = toml::parse_file(index.string());
    if (const auto file = table["gliders"][glider]["vehicle"].value<std::string>()) {
      source = (boards / *file).string() + " (" + index.string() + ", glider " + glider + ")";
      return boards / *file;
    }
  } catch (const toml::parse_error& e) {
    throw std::runtime_error(index.string() + ": " + std::string(e.description()));
  }
  throw std::runtime_error(index.string() + ": glider '" + glider +
                           "' is not listed and there is no health/vehicle.toml nor vehicle.toml in " +
                           glider_dir.string() + ": give --vehicle FILE");
}

// Each surfacing's estimate of the current over the segment before it. The
// glider's estimate is the fix's offset from its dead reckoning over the
// time under water: it also holds the DR's own speed error, which the model
// flies without. With `ratio` (true over DR speed through the water, from the
// model) that part is taken out: the DR's through-water track of the segment
// (its position on surfacing less the fix it dived from and the current it
// already carried) times (ratio - 1), over the time.
// The current history[i] measured over the segment that ended there (the
// one before it dived from), with the DR's share out as current_samples
// takes it; as measured where the segment's DR is not known.
fw::EastNorth measured_current(const std::vector<Surfacing>& history, std::size_t i, double ratio) {
  const Surfacing& s = history[i];
  fw::EastNorth c{*s.water_vx_m_s, *s.water_vy_m_s};
  if (i == 0 || ratio == 1.0) return c;
  const Surfacing& before = history[i - 1];
  if (!before.has_fix() || !s.dr_lat_deg || !s.dr_lon_deg) return c;
  const double under_s = s.call_start_utc_s - before.call_end_utc_s;
  if (!(under_s > 0.0)) return c;
  const fw::LocalFrame frame({*before.lat_deg, *before.lon_deg});
  const fw::EastNorth dr = frame.to_local({*s.dr_lat_deg, *s.dr_lon_deg});
  const double carried_e = before.water_vx_m_s.value_or(0.0), carried_n = before.water_vy_m_s.value_or(0.0);
  c.east_m -= (ratio - 1.0) * (dr.east_m - carried_e * under_s) / under_s;
  c.north_m -= (ratio - 1.0) * (dr.north_m - carried_n * under_s) / under_s;
  return c;
}

}  // namespace

std::vector<CurrentSample> current_samples(const std::vector<Surfacing>& history, double ratio, double first_span_s) {
  std::vector<CurrentSample> out;
  // The first event's estimate is the mean over the segment that ended at
  // its call, which began before the history: as long as the segments the
  // mission flies (`first_span_s`, the coming dive's expected length).
  if (!history.empty() && history[0].water_vx_m_s && history[0].water_vy_m_s) {
    out.push_back({history[0].call_start_utc_s - 0.5 * first_span_s, *history[0].water_vx_m_s, *history[0].water_vy_m_s,
                   first_span_s});
  }
  for (std::size_t i = 1; i < history.size(); ++i) {
    const Surfacing& s = history[i];
    const Surfacing& before = history[i - 1];
    if (!s.water_vx_m_s || !s.water_vy_m_s) continue;
    // Only a surfacing whose estimate was updated at this call is news (the
    // firmware skips segments under 10 min and those without a fix).
    if (!s.has_fix()) continue;
    const double under_s = s.call_start_utc_s - before.call_end_utc_s;
    if (!(under_s >= 600.0)) continue;
    const fw::EastNorth c = measured_current(history, i, ratio);
    out.push_back({0.5 * (s.call_start_utc_s + before.call_end_utc_s), c.east_m, c.north_m, under_s});
  }
  return out;
}

namespace {

void summarise(const std::vector<RunOutcome>& runs, const fw::LatLon& fix, Forecast& f) {
  std::vector<double> e, n, t;
  int aborts = 0;
  for (const RunOutcome& r : runs) {
    if (r.aborted || !r.surfaced) {
      ++aborts;
      f.abort_causes[r.cause] += 1.0;
    }
    if (r.surfaced && !r.aborted) {
      e.push_back(r.east_m);
      n.push_back(r.north_m);
      t.push_back(r.time_s);
    }
  }
  for (auto& [cause, count] : f.abort_causes) count /= static_cast<double>(runs.size());
  f.abort_risk = runs.empty() ? 0.0 : static_cast<double>(aborts) / static_cast<double>(runs.size());
  f.runs = static_cast<int>(runs.size());
  if (e.empty()) return;
  f.have_surfacing = true;
  // The position: the median over the antithetic pairs' midpoints (runs
  // 2k and 2k+1 drew opposite water, drag and trim: their midpoint has the
  // draws' linear part cancelled, and the median keeps a few runs that fly
  // off - a stall, a waypoint reached - from moving it); a pair with a run
  // that did not surface normally is left out. Without a whole pair, the
  // runs' median.
  std::vector<double> mid_e, mid_n;
  for (std::size_t i = 0; i + 1 < runs.size(); i += 2) {
    const RunOutcome& a = runs[i];
    const RunOutcome& b = runs[i + 1];
    if (a.surfaced && !a.aborted && b.surfaced && !b.aborted) {
      mid_e.push_back(0.5 * (a.east_m + b.east_m));
      mid_n.push_back(0.5 * (a.north_m + b.north_m));
    }
  }
  f.east_m = percentile(mid_e.empty() ? e : mid_e, 0.5);
  f.north_m = percentile(mid_n.empty() ? n : mid_n, 0.5);
  const fw::LatLon at = fw::LocalFrame(fix).to_global({f.east_m, f.north_m});
  f.lat_deg = at.lat_deg;
  f.lon_deg = at.lon_deg;
  f.time_utc_s = f.dive_utc_s + percentile(t, 0.5);
  f.time_p10_utc_s = f.dive_utc_s + percentile(t, 0.1);
  f.time_p90_utc_s = f.dive_utc_s + percentile(t, 0.9);
  // 95 % ellipse of the runs' scatter (chi-square, 2 degrees of freedom).
  double me = 0.0, mn = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    me += e[i];
    mn += n[i];
  }
  me /= static_cast<double>(e.size());
  mn /= static_cast<double>(e.size());
  double cee = 0.0, cnn = 0.0, cen = 0.0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    cee += (e[i] - me) * (e[i] - me);
    cnn += (n[i] - mn) * (n[i] - mn);
    cen += (e[i] - me) * (n[i] - mn);
  }
  const double d = std::max<double>(1.0, static_cast<double>(e.size()) - 1.0);
  cee /= d;
  cnn /= d;
  cen /= d;
  const double tr = 0.5 * (cee + cnn), det = cee * cnn - cen * cen;
  const double disc = std::sqrt(std::max(0.0, tr * tr - det));
  const double l1 = tr + disc, l2 = std::max(0.0, tr - disc);
  const double chi2_95 = 5.991464547107979;
  f.ellipse.semi_major_m = std::sqrt(chi2_95 * l1);
  f.ellipse.semi_minor_m = std::sqrt(chi2_95 * l2);
  // Major axis direction (east, north) = (cen, l1 - cee) or (l1 - cnn, cen).
  double ve = cen, vn = l1 - cee;
  if (std::hypot(ve, vn) < 1e-12) {
    ve = l1 - cnn;
    vn = cen;
  }
  if (std::hypot(ve, vn) < 1e-12) {
    ve = 0.0;
    vn = 1.0;
  }
  double bearing = std::atan2(ve, vn) * 180.0 / std::numbers::pi;
  if (bearing < 0.0) bearing += 180.0;
  if (bearing >= 180.0) bearing -= 180.0;
  f.ellipse.orientation_deg = bearing;
}

// What the runs' draws (current, drag, trim) leave out, the model's own
// miss on the recent dives flown again with the current each measured (in
// the SIL truths of nsb3.mi up to 0.9 km on 3 h dives whose current the
// forecast predicted within 0.01 m/s): each run moved by a Gaussian of the
// misses' second moments (a miss that repeats, a bias, is spread, not
// corrected). Its draws come from their own stream of the run's seed: the
// same whatever the thread count.
void add_model_miss(Forecast& f, const ForecastOptions& options, std::vector<RunOutcome>& runs) {
  if (f.model_miss_dives == 0) return;
  const double se = f.model_miss_east_m, sn = f.model_miss_north_m, rho = f.model_miss_correlation;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    RunOutcome& r = runs[i];
    if (!r.surfaced) continue;
    // Antithetic pairs, as the runs' own draws (monte_carlo.cpp).
    sil::PortableRandom draw(sil::derived_seed(options.seed + (i & ~std::size_t{1}), 0x6d697373ULL));
    const double sign = (i & 1U) != 0U ? -1.0 : 1.0;
    const double g1 = sign * draw.gaussian(), g2 = sign * draw.gaussian();
    r.east_m += se * g1;
    r.north_m += sn * (rho * g1 + std::sqrt(std::max(0.0, 1.0 - rho * rho)) * g2);
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "the model's miss on %d recent dives flown again with their measured current: %.0f m E, %.0f m N "
                "(RMS), added to the runs' spread",
                f.model_miss_dives, se, sn);
  f.notes.push_back(text);
}

bool list_done(const fw::MissionPlan& plan, std::int32_t reached) {
  if (plan.waypoint_count == 0 || plan.legs_to_run == fw::kLegsLoopForever) return false;
  const std::int32_t legs = plan.legs_to_run == fw::kLegsOnce ? plan.waypoint_count : plan.legs_to_run;
  return reached >= legs;
}

void advance(MissionNow& now, std::int32_t count) {
  for (std::int32_t i = 0; i < count && !list_done(now.config.plan, now.waypoints_reached); ++i) {
    ++now.waypoints_reached;
    now.active_waypoint = (now.active_waypoint + 1) % now.config.plan.waypoint_count;
  }
}

// Which waypoint the glider flies to now: its own arrivals, replayed. Under
// water the firmware counts a waypoint when its dead reckoning comes within
// the radius, which no fix shows: each segment since the last plan change is
// flown once in SIL (nominal vehicle, the current the glider measured over
// that segment, its navigator's belief from the dive) and the waypoints the
// firmware counted are counted; at each fix, its surface test (the fix
// within the radius) too.
// Slocum's start_when 9 is periodic (firmware navigator.cpp): the clock that
// ended a dive restarted when it fired, somewhere in the glider's last yo,
// and the glider climbed on to the surface from there. The longest such climb
// is from the bottom of a yo: a yo's climb (inflection to climb_to_m, from
// one still-water flight of the plan's first hour) and on to the surface.
// 0 when the plan has no when_secs clock or the flight no yo.
double longest_climb_left_s(const FlightSetup& setup, const ForecastOptions& options) {
  if (!(setup.config.plan.surface_interval_s > 0.0)) return 0.0;
  FlightSetup still = setup;
  still.current = CurrentEstimate{};
  ForecastOptions one = options;
  one.threads = 1;
  one.max_dive_s = 3600.0;
  const double yo_climb_s = fly_runs(still, one, 1, false).at(0).yo_climb_s;
  const fw::YoMissionConfig& m = setup.config.mission;
  const double span = m.dive_to_m - m.climb_to_m;
  return span > 0.0 ? yo_climb_s * m.dive_to_m / span : yo_climb_s;
}

// The model's own check of the firmware's dead reckoning: one still-water
// flight of the setup's dive, true over dead-reckoned distance (1: none).
double model_dr_ratio(const FlightSetup& setup, const ForecastOptions& options) {
  FlightSetup still = setup;
  still.current = CurrentEstimate{};
  still.firmware_current.reset();
  const RunOutcome r = fly_runs(still, options, 1, false).at(0);
  const double dr = std::hypot(r.dr_east_m, r.dr_north_m), truth = std::hypot(r.east_m, r.north_m);
  return r.surfaced && !r.aborted && dr > 100.0 && truth / dr > 0.5 && truth / dr < 2.0 ? truth / dr : 1.0;
}

// A dive the replay flew again: the fix less where the model put it (m).
struct DiveMiss {
  double utc_s = 0.0;
  double east_m = 0.0, north_m = 0.0;
};

// Each past dive flown again by the model, with the current measured over
// it less the glider's DR share (`dr_ratio`, as current_samples): the raw
// measure holds the DR's speed error, which a model flying the true speed
// would count twice (a glider whose DR reads 9 % slow replayed 9 % too far,
// past a waypoint it did not reach).
void replay_waypoints(MissionNow& now, const std::vector<Surfacing>& history, const FlightSetup& base,
                      const ForecastOptions& options, double longest_climb_s, double dr_ratio,
                      std::vector<DiveMiss>& misses) {
  const fw::MissionPlan& plan = now.config.plan;
  if (plan.waypoint_count == 0) return;
  const Surfacing* previous = nullptr;
  for (std::size_t i = now.replay_from; i < history.size(); ++i) {
    const Surfacing& s = history[i];
    if (previous != nullptr && !list_done(plan, now.waypoints_reached)) {
      FlightSetup segment = base;
      segment.config.plan = remaining_plan(now);
      segment.fix = {*previous->lat_deg, *previous->lon_deg};
      segment.surface_time_s = std::max(0.0, previous->call_end_utc_s - previous->call_start_utc_s);
      segment.clock_fired_before_s = climb_left_at_firing_s(history, i - 1, plan, longest_climb_s);
      const bool measured = s.water_vx_m_s && s.water_vy_m_s;
      const fw::EastNorth c =
          measured ? measured_current(history, i, dr_ratio)
                   : fw::EastNorth{previous->water_vx_m_s.value_or(0.0), previous->water_vy_m_s.value_or(0.0)};
      segment.current.east_m_s = c.east_m;
      segment.current.north_m_s = c.north_m;
      segment.firmware_current.reset();
      if (previous->water_vx_m_s && previous->water_vy_m_s) {
        segment.firmware_current = fw::EastNorth{*previous->water_vx_m_s, *previous->water_vy_m_s};
      }
      ForecastOptions one = options;
      one.threads = 1;
      one.max_dive_s = std::max(600.0, s.call_start_utc_s - previous->call_end_utc_s + 300.0);
      const RunOutcome r = fly_runs(segment, one, 1, false).at(0);
      advance(now, r.waypoints_reached);
      if (r.surfaced && !r.aborted && s.has_fix()) {
        const fw::EastNorth at = fw::LocalFrame(segment.fix).to_local({*s.lat_deg, *s.lon_deg});
        misses.push_back({s.call_start_utc_s, at.east_m - r.east_m, at.north_m - r.north_m});
      }
    }
    previous = nullptr;
    if (!s.has_fix()) continue;
    previous = &s;
    const fw::LocalFrame frame({*s.lat_deg, *s.lon_deg});
    const fw::EastNorth w = frame.to_local(plan.waypoints[static_cast<std::size_t>(now.active_waypoint)]);
    if (std::hypot(w.east_m, w.north_m) <= plan.waypoint_radius_m) advance(now, 1);
  }
}

}  // namespace

Forecast make_forecast(const fs::path& glider_dir, const ForecastOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (!fs::is_directory(glider_dir)) throw std::runtime_error(glider_dir.string() + ": not a glider folder");
  Forecast f;
  const std::vector<Surfacing> history = read_surfacings(glider_dir);
  const Surfacing* last = nullptr;
  for (const Surfacing& s : history) {
    if (s.has_fix()) last = &s;
  }
  if (last == nullptr) {
    throw std::runtime_error((glider_dir / "logs").string() +
                             ": no surfacing event with a GPS fix (logs/*.surfacing.json): nothing to forecast from");
  }
  if (last != &history.back()) {
    f.notes.push_back("the last call (" + history.back().file.filename().string() +
                      ") had no fix; forecast from the fix of " + last->file.filename().string());
  }
  // The glider's own abort: after one it stays at the surface until the
  // pilot resumes or restarts the mission; the runs fly it as resumed.
  if (history.back().surfaced_by_abort) {
    f.glider_aborted = true;
    f.glider_abort_cause = history.back().last_abort_cause;
    f.notes.push_back("the glider surfaced by an abort at its last call (" + history.back().reasons +
                      (f.glider_abort_cause.empty() ? "" : "; last abort: " + f.glider_abort_cause) +
                      "): it does not dive again until the mission is resumed or restarted; the runs fly it as "
                      "resumed, and abort_risk is theirs");
  }
  f.glider = last->glider;
  f.prior = current_prior(glider_dir, options.prior);
  if (!options.tide_table.empty()) {
    f.prior.tide = std::make_shared<const TideTable>(read_tide_table(options.tide_table));
    std::string names;
    for (const TideConstituent& c : f.prior.tide->constituents) names += (names.empty() ? "" : ", ") + c.name;
    f.notes.push_back("the tide's phase from " + options.tide_table.string() + " (" + names +
                      "): the tidal prior's tide is the table's, what it may be wrong by its width");
  }
  f.fix_lat_deg = *last->lat_deg;
  f.fix_lon_deg = *last->lon_deg;
  f.fix_utc_s = last->call_start_utc_s;
  f.dive_utc_s = history.back().call_end_utc_s;
  f.made_utc_s = static_cast<double>(
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count());

  // Vehicle and mission, through the firmware's own setup.
  FlightSetup setup;
  const fs::path vfile = vehicle_file(glider_dir, f.glider, options, f.vehicle_source);
  try {
    setup.vehicle = model::load_vehicle_file(vfile);
  } catch (const config::ConfigError& e) {
    throw std::runtime_error(e.what());
  }
  const fw::app::FittedDevices fitted = sil::load_fitted_devices(vfile);
  fw::app::VehicleSetup vsetup =
      sil::vehicle_setup(setup.vehicle, fitted, options.max_working_depth_m, false, setup.vehicle.trim_density_kg_m3);
  vsetup.source = vfile.string();
  const fs::path mission = find_mission(glider_dir, options.mission, last->mission_name);
  MissionNow now = mission_now(glider_dir, mission, vsetup, history, options.rehearse, options.include_queue);
  f.mission = mission.filename().string();
  f.queued_applied = now.applied;
  for (const std::string& note : now.notes) f.notes.push_back(note);
  if (!now.refusal.empty()) {
    f.refusal = now.refusal;
    f.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return f;
  }
  setup.config = now.config;
  setup.fix = {f.fix_lat_deg, f.fix_lon_deg};
  if (history.back().water_vx_m_s && history.back().water_vy_m_s) {
    setup.firmware_current = fw::EastNorth{*history.back().water_vx_m_s, *history.back().water_vy_m_s};
  }
  const model::VehicleParams nominal_vehicle = setup.vehicle;  // the baseline's (measure_speed may correct it)
  measure_speed(history, glider_dir, setup, options, f);
  // The glider's firmware dead-reckons through its pitch sensor, whose scale
  // measure_speed read: the model's firmware counts the same way, so the
  // waypoint arrivals it judges on its DR, and the DR share of each current
  // estimate (model_dr_ratio), are the glider's. Its DR counting the true
  // speed while carrying the glider's belief (which holds the glider's DR
  // error) replayed a glider whose DR reads 9 % slow onto a waypoint its
  // DR never reached.
  // The baseline's (the file's DR; the vehicle file's flight, not the depth-rate calibrated one).
  const double model_average_speed_m_s =
      f.depth_rate_applied && f.nominal_average_speed_m_s > 0.0 ? f.nominal_average_speed_m_s : setup.average_speed_m_s;
  // (A servo calibrated by its depth rates already counts through its sensor: measure_speed.)
  const bool glider_dr = options.glider_dead_reckoning && options.pitch_calibration && f.pitch_samples > 0 &&
                         f.pitch_scale > 0.0 && !(f.depth_rate_applied && f.depth_rate_servo);
  // The glider's DR error its pitch sensor adds, where the model's DR does not count it.
  const double sensor_dr_factor = options.pitch_calibration && !glider_dr ? f.pitch_dr_speed_factor : 1.0;
  if (glider_dr) {
    setup.config.dead_reckoning = biased_pitch_dead_reckoning(setup.config.dead_reckoning, 1.0 / f.pitch_scale);
    // The navigator's mean speed (m_avg_speed) is its DR's: as slow.
    if (f.pitch_dr_speed_factor > 0.0) setup.average_speed_m_s /= f.pitch_dr_speed_factor;
  }
  std::vector<DiveMiss> misses;
  const double longest_climb_s = longest_climb_left_s(setup, options);
  if (options.waypoint >= 0 && now.applied.empty()) {
    if (options.waypoint >= now.config.plan.waypoint_count) {
      throw std::runtime_error("--waypoint " + std::to_string(options.waypoint) + ": the mission has " +
                               std::to_string(now.config.plan.waypoint_count) + " waypoints");
    }
    now.active_waypoint = options.waypoint;
    f.notes.push_back("active waypoint given (--waypoint), not replayed");
  } else {
    replay_waypoints(now, history, setup, options, longest_climb_s, model_dr_ratio(setup, options) * sensor_dr_factor,
                     misses);
  }
  // Only the last day's dives: older water and older trim are other ones.
  {
    // Second moments about zero, not the mean: a miss that repeats (a
    // bias) is an error too.
    double ee = 0.0, nn = 0.0, en = 0.0;
    int count = 0;
    for (const DiveMiss& m : misses) {
      if (m.utc_s <= f.fix_utc_s - 86400.0) continue;
      ee += m.east_m * m.east_m;
      nn += m.north_m * m.north_m;
      en += m.east_m * m.north_m;
      ++count;
    }
    if (count >= 2) {
      f.model_miss_dives = count;
      f.model_miss_east_m = std::sqrt(ee / count);
      f.model_miss_north_m = std::sqrt(nn / count);
      f.model_miss_correlation = ee > 0.0 && nn > 0.0 ? en / std::sqrt(ee * nn) : 0.0;
    }
  }
  setup.config.plan = remaining_plan(now);
  setup.surface_time_s = std::max(0.0, f.dive_utc_s - history.back().call_start_utc_s);
  setup.clock_fired_before_s = climb_left_at_firing_s(history, history.size() - 1, now.config.plan, longest_climb_s);
  if (history.back().mission_time_s >= 0.0 && std::isfinite(now.config.mission.max_duration_s)) {
    const double mt_at_dive = history.back().mission_time_s + (f.dive_utc_s - history.back().call_start_utc_s);
    setup.overtime_left_s = now.config.mission.max_duration_s - mt_at_dive;
    if (setup.overtime_left_s <= 0.0) setup.overtime_left_s = 1.0;
  }
  if (now.config.plan.waypoint_count > 0) {
    f.notes.push_back("flying to waypoint " + std::to_string(now.active_waypoint) + " of " +
                      std::to_string(now.config.plan.waypoint_count) + " (" + std::to_string(now.waypoints_reached) +
                      " reached since the mission or its last change)");
  }

  // The current: the estimate over the coming dive (its length from the
  // last segment, or the surfacing interval), and the persistence baseline.
  // The model's own check of the firmware's dead reckoning: one still-water
  // flight of the coming dive, true against dead-reckoned distance.
  f.dr_speed_ratio = model_dr_ratio(setup, options);
  // when_secs counts from its firing, a climb before the arrival: the dive is shorter by the time
  // spent up (the climb left then and the coming one's are alike on average: climb_left_at_firing_s).
  double expected_s = now.config.plan.surface_interval_s > 0.0
                          ? std::max(60.0, now.config.plan.surface_interval_s - setup.surface_time_s)
                          : 3600.0;
  if (history.size() >= 2) {
    const double last_dive = history.back().call_start_utc_s - history[history.size() - 2].call_end_utc_s;
    if (last_dive > 60.0) expected_s = std::min(expected_s, last_dive);
  }
  // The glider's DR speed error (the model's DR counts as the glider's, its pitch sensor's scale included):
  // its share of each estimate out.
  const double glider_dr_ratio = f.dr_speed_ratio * sensor_dr_factor;
  const std::vector<CurrentSample> samples = current_samples(history, glider_dr_ratio, expected_s);
  f.current = estimate_current(samples, f.dive_utc_s, f.dive_utc_s + expected_s, f.prior);
  f.favoured = favoured_prior(samples, f.dive_utc_s, f.prior);
  if (f.prior.mode == PriorMode::kEvidence && !samples.empty()) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "the estimates favour a mean current of +- %.3f m/s and an M2 tide of +- %.3f m/s per component, "
                  "each estimate off by +- %.0f m over its segment (the prior's %.3f, %.3f and %.0f, weighted by "
                  "their evidence)",
                  f.favoured.mean_sigma_m_s, f.favoured.m2_sigma_m_s, f.favoured.position_sigma_m,
                  f.prior.mean_sigma_m_s, f.prior.m2_sigma_m_s, f.prior.position_sigma_m);
    f.notes.push_back(text);
    if (f.prior.tide) {
      std::snprintf(text, sizeof text,
                    "with the tide table the M2 width is the table's errors, which the estimates favour x%.2f",
                    f.favoured.tide_error_scale);
      f.notes.push_back(text);
    }
  }
  f.baseline_current = last_current(current_samples(history, 1.0, expected_s));
  if (samples.empty()) {
    f.notes.push_back("no depth-averaged current from the surfacings yet (m_water_vx/vy): still water +- " +
                      std::to_string(f.current.sigma_east_m_s).substr(0, 4) + " m/s assumed");
  }

  setup.current = f.current;
  // The replayed dives' miss already holds the true vehicle's error (they
  // flew the nominal one): with it, the vehicle is not drawn as well.
  ForecastOptions drawn = options;
  if (f.model_miss_dives > 0) drawn.drag_sigma = drawn.buoyancy_sigma_kg = 0.0;
  // The speed term's drag sigma (its pitch calibration's; speed_term.cpp) on top of the drawn drag's.
  if (f.model_miss_dives == 0) drawn.drag_sigma = std::hypot(drawn.drag_sigma, f.speed_drag_sigma);
  std::vector<RunOutcome> runs = fly_runs(setup, drawn, options.runs, true);
  add_model_miss(f, options, runs);
  summarise(runs, setup.fix, f);

  FlightSetup base = setup;
  base.current = f.baseline_current;
  base.vehicle = nominal_vehicle;                          // the baseline flies the nominal vehicle
  base.config.mission = now.config.mission;                // the mission's own pitch
  base.config.dead_reckoning = now.config.dead_reckoning;  // and its DR as the file's
  base.average_speed_m_s = model_average_speed_m_s;
  const std::vector<RunOutcome> baseline = fly_runs(base, options, 1, false);
  if (!baseline.empty() && baseline[0].surfaced && !baseline[0].aborted) {
    f.baseline_ok = true;
    f.baseline_east_m = baseline[0].east_m;
    f.baseline_north_m = baseline[0].north_m;
    const fw::LatLon at = fw::LocalFrame(setup.fix).to_global({baseline[0].east_m, baseline[0].north_m});
    f.baseline_lat_deg = at.lat_deg;
    f.baseline_lon_deg = at.lon_deg;
    f.baseline_time_utc_s = f.dive_utc_s + baseline[0].time_s;
  }
  f.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  if (options.write) write_atomically(glider_dir / "forecast" / "forecast.json", forecast_json(f).dump(2) + "\n");
  return f;
}

nlohmann::json forecast_json(const Forecast& f) {
  using nlohmann::json;
  json out{{"schema", "glider-forecast/1"}, {"glider", f.glider}, {"made_utc", format_utc(f.made_utc_s)}};
  out["from_fix"] = {{"lat_deg", f.fix_lat_deg}, {"lon_deg", f.fix_lon_deg}, {"utc", format_utc(f.fix_utc_s)}};
  out["dive_utc"] = format_utc(f.dive_utc_s);
  if (f.have_surfacing) {
    out["next_surfacing"] = {{"lat_deg", f.lat_deg},
                             {"lon_deg", f.lon_deg},
                             {"east_m", f.east_m},
                             {"north_m", f.north_m},
                             {"time_utc", format_utc(f.time_utc_s)},
                             {"time_p10_utc", format_utc(f.time_p10_utc_s)},
                             {"time_p90_utc", format_utc(f.time_p90_utc_s)},
                             {"ellipse",
                              {{"level", 0.95},
                               {"semi_major_m", f.ellipse.semi_major_m},
                               {"semi_minor_m", f.ellipse.semi_minor_m},
                               {"orientation_deg", f.ellipse.orientation_deg}}}};
  } else {
    out["next_surfacing"] = nullptr;
  }
  out["abort_risk"] = f.abort_risk;
  out["glider_aborted"] = f.glider_aborted ? json{{"cause", f.glider_abort_cause}} : json(nullptr);
  out["abort_causes"] = json::object();
  for (const auto& [cause, fraction] : f.abort_causes) out["abort_causes"][cause] = fraction;
  out["current"] = {{"east_m_s", f.current.east_m_s},
                    {"north_m_s", f.current.north_m_s},
                    {"sigma_east_m_s", f.current.sigma_east_m_s},
                    {"sigma_north_m_s", f.current.sigma_north_m_s},
                    {"method", f.current.method},
                    {"samples", f.current.samples},
                    {"dr_speed_ratio", f.dr_speed_ratio},
                    {"glider_speed_ratio", f.glider_speed_ratio},
                    {"speed_drag_factor", f.speed_drag_factor},
                    {"speed_dives", f.speed_dives},
                    {"speed_drag_sigma", f.speed_drag_sigma},
                    {"pitch_scale", f.pitch_scale},
                    {"pitch_scale_sigma", f.pitch_scale_sigma},
                    {"pitch_samples", f.pitch_samples},
                    {"pitch_dr_speed_factor", f.pitch_dr_speed_factor},
                    {"prior",
                     {{"mode", to_string(f.prior.mode)},
                      {"mean_sigma_m_s", f.prior.mean_sigma_m_s},
                      {"m2_sigma_m_s", f.prior.m2_sigma_m_s},
                      {"estimate_sigma_m_s", f.prior.estimate_sigma_m_s},
                      {"favoured_mean_sigma_m_s", f.favoured.mean_sigma_m_s},
                      {"favoured_m2_sigma_m_s", f.favoured.m2_sigma_m_s},
                      {"position_sigma_m", f.prior.position_sigma_m},
                      {"favoured_position_sigma_m", f.favoured.position_sigma_m},
                      {"tide_table", f.prior.tide ? f.prior.tide->source : ""}}}};
  out["depth_rate"] = {{"read", f.depth_rate_have},
                       {"applied", f.depth_rate_applied},
                       {"servo", f.depth_rate_servo},
                       {"pitch_scale", f.depth_rate_pitch_scale},
                       {"drag_factor", f.depth_rate_drag_factor},
                       {"buoyancy_g", 1000.0 * f.depth_rate_buoyancy_kg},
                       {"glider_dive_m_s", f.depth_rate_glider_dive_m_s},
                       {"glider_climb_m_s", f.depth_rate_glider_climb_m_s},
                       {"model_dive_m_s", f.depth_rate_model_dive_m_s},
                       {"model_climb_m_s", f.depth_rate_model_climb_m_s}};
  out["model_miss"] = {{"dives", f.model_miss_dives},
                       {"rms_east_m", f.model_miss_east_m},
                       {"rms_north_m", f.model_miss_north_m},
                       {"correlation", f.model_miss_correlation}};
  if (f.baseline_ok) {
    out["baseline"] = {{"lat_deg", f.baseline_lat_deg},
                       {"lon_deg", f.baseline_lon_deg},
                       {"time_utc", format_utc(f.baseline_time_utc_s)},
                       {"current_east_m_s", f.baseline_current.east_m_s},
                       {"current_north_m_s", f.baseline_current.north_m_s},
                       {"what", "last depth-averaged current persists"}};
  } else {
    out["baseline"] = {{"lat_deg", nullptr}, {"lon_deg", nullptr}, {"what", "last depth-averaged current persists"}};
  }
  out["runs"] = f.runs;
  out["wall_s"] = f.wall_s;
  out["mission"] = f.mission;
  out["vehicle"] = f.vehicle_source;
  out["queued_applied"] = f.queued_applied;
  out["notes"] = f.notes;
  if (!f.refusal.empty()) out["refusal"] = f.refusal;
  return out;
}

std::string forecast_text(const Forecast& f) {
  char line[512];
  std::string out;
  std::snprintf(line, sizeof line, "forecast for %s, mission %s (%d runs, %.2f s)\n", f.glider.c_str(),
                f.mission.c_str(), f.runs, f.wall_s);
  out += line;
  std::snprintf(line, sizeof line, "  from fix   : %.5f N %.5f E at %s, dive %s\n", f.fix_lat_deg, f.fix_lon_deg,
                format_utc(f.fix_utc_s).c_str(), format_utc(f.dive_utc_s).c_str());
  out += line;
  if (!f.refusal.empty()) return out + "  REFUSED    : " + f.refusal + "\n";
  std::snprintf(line, sizeof line, "  current    : %+.3f E %+.3f N m/s (+- %.3f, %.3f; %s of %d)\n", f.current.east_m_s,
                f.current.north_m_s, f.current.sigma_east_m_s, f.current.sigma_north_m_s, f.current.method.c_str(),
                f.current.samples);
  out += line;
  if (f.have_surfacing) {
    std::snprintf(line, sizeof line,
                  "  next surfacing: %.5f N %.5f E (%.0f m E, %.0f m N of the fix), 95 %% ellipse %.0f x %.0f m "
                  "(major axis %.0f deg)\n",
                  f.lat_deg, f.lon_deg, f.east_m, f.north_m, f.ellipse.semi_major_m, f.ellipse.semi_minor_m,
                  f.ellipse.orientation_deg);
    out += line;
    std::snprintf(line, sizeof line, "  time       : %s (p10 %s, p90 %s)\n", format_utc(f.time_utc_s).c_str(),
                  format_utc(f.time_p10_utc_s).c_str(), format_utc(f.time_p90_utc_s).c_str());
    out += line;
  } else {
    out += "  next surfacing: none of the runs surfaced normally\n";
  }
  std::snprintf(line, sizeof line, "  abort risk : %.0f %%", 100.0 * f.abort_risk);
  out += line;
  for (const auto& [cause, fraction] : f.abort_causes) {
    std::snprintf(line, sizeof line, "  %s %.0f %%", cause.c_str(), 100.0 * fraction);
    out += line;
  }
  out += "\n";
  if (f.baseline_ok) {
    std::snprintf(line, sizeof line,
                  "  baseline (last depth-averaged current %+.3f E %+.3f N m/s persists): %.5f N %.5f E at %s, "
                  "%.0f m from the forecast\n",
                  f.baseline_current.east_m_s, f.baseline_current.north_m_s, f.baseline_lat_deg, f.baseline_lon_deg,
                  format_utc(f.baseline_time_utc_s).c_str(),
                  std::hypot(f.baseline_east_m - f.east_m, f.baseline_north_m - f.north_m));
    out += line;
  }
  for (const std::string& a : f.queued_applied) out += "  applied    : " + a + "\n";
  for (const std::string& n : f.notes) out += "  note       : " + n + "\n";
  return out;
}

Rehearsal rehearse(const fs::path& glider_dir, const fs::path& file, ForecastOptions options) {
  Rehearsal r;
  r.file = file.filename().string();
  if (!fs::is_regular_file(file)) throw std::runtime_error(file.string() + ": not a readable file");
  if (file.extension() != ".ma" && file.extension() != ".mi") {
    throw std::runtime_error(file.string() + ": only a .ma or .mi can be rehearsed");
  }
  options.rehearse.push_back(file);
  options.write = false;
  r.forecast = make_forecast(glider_dir, options);
  if (!r.forecast.refusal.empty()) {
    r.verdict = "refused";
    r.message = r.forecast.refusal;
  } else if (r.forecast.abort_risk >= kAbortVerdictRisk) {
    r.verdict = "aborts";
    std::string causes;
    for (const auto& [cause, fraction] : r.forecast.abort_causes) {
      char part[96];
      std::snprintf(part, sizeof part, "%s%s %.0f %%", causes.empty() ? "" : ", ", cause.c_str(), 100.0 * fraction);
      causes += part;
    }
    char text[256];
    std::snprintf(text, sizeof text, "the rehearsal aborts in %.0f %% of %d runs (%s)", 100.0 * r.forecast.abort_risk,
                  r.forecast.runs, causes.c_str());
    r.message = std::string(text);
  } else {
    r.verdict = "ok";
    char text[160];
    std::snprintf(text, sizeof text, "flies to the next surfacing in %d runs; abort risk %.0f %%", r.forecast.runs,
                  100.0 * r.forecast.abort_risk);
    r.message = text;
  }
  write_atomically(glider_dir / "forecast" / "rehearsals" / (file.filename().string() + ".json"),
                   rehearsal_json(r, r.forecast.glider).dump(2) + "\n");
  return r;
}

nlohmann::json rehearsal_json(const Rehearsal& r, const std::string& glider) {
  nlohmann::json f = forecast_json(r.forecast);
  return {{"schema", "glider-rehearsal/1"},
          {"glider", glider},
          {"file", r.file},
          {"verdict", r.verdict},
          {"message", r.message},
          {"abort_risk", f["abort_risk"]},
          {"abort_causes", f["abort_causes"]},
          {"next_surfacing", f["next_surfacing"]},
          {"forecast", f}};
}

int rehearsal_exit_code(const Rehearsal& r) {
  if (r.verdict == "ok") return 0;
  if (r.verdict == "aborts") return 4;
  return 1;
}

std::string forecast_after_surfacing(const fs::path& glider_dir) {
  try {
    ForecastOptions options;
    const Forecast f = make_forecast(glider_dir, options);
    char text[400];
    if (!f.refusal.empty()) return "forecast: the mission is refused: " + f.refusal;
    const std::string aborted = f.glider_aborted ? "; the glider surfaced by an abort (" + f.glider_abort_cause +
                                                       "): it waits for the pilot, the runs fly it as resumed"
                                                 : "";
    if (!f.have_surfacing) {
      std::snprintf(text, sizeof text, "forecast: no run surfaces normally; abort risk %.0f %% (%.1f s)",
                    100.0 * f.abort_risk, f.wall_s);
    } else {
      std::snprintf(text, sizeof text,
                    "forecast: next surfacing %.5f N %.5f E at %s (95 %% ellipse %.0f x %.0f m), abort risk %.0f %% "
                    "(%d runs, %.1f s)",
                    f.lat_deg, f.lon_deg, format_utc(f.time_utc_s).c_str(), f.ellipse.semi_major_m,
                    f.ellipse.semi_minor_m, 100.0 * f.abort_risk, f.runs, f.wall_s);
    }
    return text + aborted;
  } catch (const std::exception& e) {
    const std::string message = std::string("forecast: failed: ") + e.what();
    try {
      nlohmann::json out{{"schema", "glider-forecast/1"}, {"error", message}, {"notes", {message}}};
      write_atomically(glider_dir / "forecast" / "forecast.json", out.dump(2) + "\n");
    } catch (const std::exception&) {
      // The folder cannot be written: the returned note still says what happened.
    }
    return message;
  }
}

// Whether the surfacing `s` was the when_secs clock's (its Because: lines say
// "Every when secs"; an event that says nothing is taken as one when the plan
// has that clock: the SIL truths' and the real benchmark's events).
bool surfaced_by_when_secs(const Surfacing& s, const fw::MissionPlan& plan) {
  if (!(plan.surface_interval_s > 0.0)) return false;
  if (s.reasons.empty()) return true;
  std::string text = s.reasons;
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text.find("every when secs") != std::string::npos;
}

// How long before surfacing `last` (an index into `history`) its when_secs
// clock fired: the climb left then, tau. The clock is periodic, so two
// consecutive surfacings arrive when_secs + tau_j - tau_(j-1) apart: the
// history fixes every tau of the chain up to one constant, and each lies in
// [0, longest]; the middle of the constant's feasible interval (the chain has
// no age limit: the clock is the firmware's, not the water). A surfacing that
// restarted the clock at its arrival (another reason in its Because: lines:
// tau 0) or before the clock's first firing (mission time under when_secs:
// the clock started with the mission, tau is that mission time) anchors the
// chain exactly. With no chain (one such surfacing) that is half the longest
// climb - the mean over a firing uniform in the yo (at u of a dive the climb
// from that depth is u of a climb, at u of a climb 1 - u of it); a history
// the rule does not fit (an empty interval) gets the same half.
double climb_left_at_firing_s(const std::vector<Surfacing>& history, std::size_t last, const fw::MissionPlan& plan,
                              double longest_s) {
  if (!(plan.surface_interval_s > 0.0) || last >= history.size()) return 0.0;
  const double period = plan.surface_interval_s;
  // The tau a surfacing is known to have, if it is one the chain cannot pass.
  auto anchored = [&](const Surfacing& s) -> std::optional<double> {
    if (!surfaced_by_when_secs(s, plan)) return 0.0;
    if (s.mission_time_s >= 0.0 && s.mission_time_s < period) return s.mission_time_s;
    return std::nullopt;
  };
  if (const std::optional<double> tau = anchored(history[last])) return *tau;
  if (!(longest_s > 0.0)) return 0.0;
  // tau_j = tau_last + d_j; the feasible tau_last: lo..hi.
  double d = 0.0, lo = 0.0, hi = longest_s;
  for (std::size_t j = last; j > 0; --j) {
    const Surfacing& now = history[j];
    const Surfacing& before = history[j - 1];
    const std::optional<double> tau = anchored(before);
    const double between = now.call_start_utc_s - before.call_start_utc_s;
    // A dive between them that the clock ended (not a call dropped and redialled).
    if (!(before.call_end_utc_s < now.call_start_utc_s) || between > period + longest_s) break;
    if (!tau && between < 0.5 * period) break;
    d -= between - period;
    if (tau) return std::clamp(*tau - d, lo, std::max(lo, hi));
    lo = std::max(lo, -d);
    hi = std::min(hi, longest_s - d);
  }
  return lo <= hi ? 0.5 * (lo + hi) : 0.5 * longest_s;
}

}  // namespace glider::forecast
