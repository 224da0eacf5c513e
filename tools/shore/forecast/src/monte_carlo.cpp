// SPDX-License-Identifier: Apache-2.0
// The Monte-Carlo flights: each run the real firmware against the vehicle
// model (glider::sil::run_scenario, in-process), from the fix at the surface
// to the next surfacing, with its own current and vehicle drawn.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <thread>

#include "glider/firmware/geo.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider/model/environment.hpp"
#include "glider/sil/portable_random.hpp"
#include "glider/sil/scenario.hpp"

namespace glider::forecast {
namespace {

// Below this the antenna is out (sil GpsModel::antenna_out_depth_m).
constexpr double kAntennaOutDepthM = 0.3;

RunOutcome fly_one(const FlightSetup& s, const ForecastOptions& o, std::uint64_t seed, std::uint64_t draw_seed,
                   double sign, bool vary) {
  // The draws come from their own stream: the SIL's noise streams use `seed` itself.
  sil::PortableRandom draw(sil::derived_seed(draw_seed, 0x666f7265ULL));
  model::VehicleParams vehicle = s.vehicle;
  double east = s.current.east_m_s, north = s.current.north_m_s;
  if (vary) {
    east += sign * s.current.sigma_east_m_s * draw.gaussian();
    north += sign * s.current.sigma_north_m_s * draw.gaussian();
    const double drag = std::exp(sign * o.drag_sigma * draw.gaussian());
    model::scale_drag(vehicle.hydro, drag);
    vehicle.buoyancy_offset_kg += sign * o.buoyancy_sigma_kg * draw.gaussian();
  }
  sil::ScenarioOptions opt;
  opt.seed = seed;
  model::WaterSample water;
  water.density_kg_m3 = vehicle.trim_density_kg_m3;
  water.current_east_m_s = east;
  water.current_north_m_s = north;
  opt.environment = model::Environment{model::WaterColumn({model::ProfileNode{0.0, water}}, model::Oscillation{})};
  opt.peripherals.gps.launch = s.fix;
  opt.peripherals.gps.time_to_first_fix_min_s = 1.0;
  opt.peripherals.gps.time_to_first_fix_max_s = 2.0;
  opt.max_sim_time_s = o.max_dive_s;
  opt.stop_after_abort_s = 3600.0;
  fw::FlightSoftwareConfig config = s.config;
  // The call is over: it dives as soon as it has a fix.
  config.plan.surface_dwell_s = 0.0;
  config.plan.gps_wait_s = 60.0;
  if (s.overtime_left_s > 0.0) config.mission.max_duration_s = std::max(1.0, s.overtime_left_s);
  if (config.plan.waypoint_count > 0) {
    const fw::LocalFrame frame(s.fix);
    const fw::EastNorth w = frame.to_local(config.plan.waypoints[0]);
    opt.heading_deg = std::fmod(rad_to_deg(std::atan2(w.east_m, w.north_m)) + 360.0, 360.0);
  } else if (std::isfinite(config.plan.heading_rad)) {
    opt.heading_deg = rad_to_deg(config.plan.heading_rad);
  }
  // The navigator steers and dead-reckons with what the glider believes (its
  // m_water_vx/vy at the dive), not with the forecast's own estimate of the
  // water: the two differ whenever the forecast expects the current to change.
  const std::optional<fw::EastNorth> belief = s.firmware_current;
  const double up_s = s.surface_time_s, fired_s = s.surface_time_s + s.clock_fired_before_s;
  const double speed = s.average_speed_m_s, weight = s.average_weight_s;
  opt.before_launch = [belief, up_s, fired_s, speed, weight](fw::FlightSoftware& flight) {
    if (belief) flight.seed_current(*belief);
    flight.seed_clocks(fired_s, up_s);
    if (speed > 0.0) flight.seed_average_speed(speed, weight);
  };
  RunOutcome out;
  // Times count from the dive (the forecast's origin is the call's end, when
  // the glider dived); a run that never dives counts from its start.
  double dive_s = -1.0;
  const fw::LocalFrame frame(s.fix);
  auto record = [&out, &dive_s, &frame](double t, const model::Truth& truth, const fw::FlightSoftware& flight) {
    const fw::EastNorth dr = frame.to_local(flight.navigator().dr_position());
    out.dr_east_m = dr.east_m;
    out.dr_north_m = dr.north_m;
    out.average_speed_m_s = flight.navigator().average_speed_m_s();
    out.surfaced = true;
    out.time_s = t - std::max(0.0, dive_s);
    out.east_m = truth.east_m;
    out.north_m = truth.north_m;
  };
  // The yos' climbs (a climb that a dive ends, not the final one): their
  // mean length says how long the climb left is when the surface clock fires.
  fw::Phase phase_before = fw::Phase::kSurface;
  double climb_from = -1.0, climbs_s = 0.0;
  int climbs = 0;
  opt.stop_when = [&](double t, const fw::FlightSoftware& flight, const model::Truth& truth) {
    out.waypoints_reached = flight.navigator().waypoints_reached();
    const fw::Phase phase = flight.phase();
    if (phase != phase_before) {
      if (phase == fw::Phase::kClimb) climb_from = t;
      if (phase == fw::Phase::kDive && phase_before == fw::Phase::kClimb && climb_from >= 0.0) {
        climbs_s += t - climb_from;
        out.yo_climb_s = climbs_s / ++climbs;
      }
      phase_before = phase;
    }
    out.glide_pitch.add(truth.depth_m, truth.depth_rate_m_s, truth.pitch_rad, truth.pitch_rate_rad_s);
    if (dive_s < 0.0 && !flight.navigator().at_surface()) dive_s = t;
    if (flight.phase() == fw::Phase::kAbort) {
      if (!out.aborted) {
        out.aborted = true;
        out.cause = fw::cause_id(flight.abort_cause());
      }
      if (truth.depth_m < kAntennaOutDepthM) {
        record(t, truth, flight);
        return true;
      }
      return false;
    }
    if ((flight.navigator().segments() >= 1 && flight.navigator().at_surface()) || flight.complete()) {
      record(t, truth, flight);
      return true;
    }
    return false;
  };
  const sil::ScenarioResult result = sil::run_scenario(vehicle, config, opt);
  if (!result.error.empty()) throw std::runtime_error("SIL flight: " + result.error);
  if (!out.surfaced && !out.aborted) out.cause = "no_surfacing";
  return out;
}

}  // namespace

std::vector<RunOutcome> fly_runs(const FlightSetup& setup, const ForecastOptions& options, int n, bool vary) {
  std::vector<RunOutcome> outcomes(static_cast<std::size_t>(std::max(n, 0)));
  const int threads = std::clamp(options.threads, 1, std::max(1, n));
  std::vector<std::string> errors(static_cast<std::size_t>(threads));
  auto worker = [&](int w) {
    try {
      for (int i = w; i < n; i += threads) {
        // Antithetic pairs: run 2k+1 draws the negatives of run 2k's
        // (the same stream), so the runs' median is not moved by the
        // sampling of a wide current (variance reduction, no bias).
        const auto index = static_cast<std::uint64_t>(i);
        outcomes[static_cast<std::size_t>(i)] =
            fly_one(setup, options, options.seed + index, options.seed + (index & ~std::uint64_t{1}),
                    (index & 1U) != 0U ? -1.0 : 1.0, vary);
      }
    } catch (const std::exception& e) {
      errors[static_cast<std::size_t>(w)] = e.what();
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < threads; ++w) pool.emplace_back(worker, w);
  worker(0);
  for (std::thread& t : pool) t.join();
  for (const std::string& e : errors) {
    if (!e.empty()) throw std::runtime_error(e);
  }
  return outcomes;
}

}  // namespace glider::forecast
