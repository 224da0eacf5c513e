// SPDX-License-Identifier: Apache-2.0
#include "glider/firmware/app/mission_setup.hpp"

#include <cmath>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"

namespace glider::fw::app {
namespace {

// What a mission of either kind does not say: the heading autopilot's law
// and the vehicle's fin, and the dead reckoning.
bool base_config(const VehicleSetup& setup, const MissionOptions& options, FlightSoftwareConfig& base,
                 std::string& refusal) {
  if (options.heading) {
    base.heading = *options.heading;
  } else {
    base.heading.law = options.heading_law;
    base.heading.delay_s = setup.fin_delay_s;
    base.heading.fin_max_rad = setup.vehicle.fin_max_rad;
    base.heading.fin_rate_rad_s = setup.vehicle.fin_rate_rad_s;
    base.heading.yaw_gain_per_m = setup.vehicle.yaw_gain_per_m;
  }
  if (options.flight_model_dr) {
    if (!setup.flight_model_dr) {
      refusal = setup.source + ": flight-model dead reckoning asked for, but no angle-of-attack table is given";
      return false;
    }
    base.dead_reckoning = *setup.flight_model_dr;
  }
  return true;
}

// The firmware must not drive the servos past the vehicle's travel, and a
// device the mission relies on must be fitted.
std::string check_vehicle(const FlightSoftwareConfig& c, const VehicleSetup& setup) {
  const ActuatorLimits& l = c.limits;
  const ActuatorLimits& travel = setup.vehicle.limits;
  const double tolerance = 1e-9;
  if (!(l.ballast_min_cc >= travel.ballast_min_cc - tolerance &&
        l.ballast_max_cc <= travel.ballast_max_cc + tolerance)) {
    return "firmware ballast limits exceed the vehicle's buoyancy engine (" + setup.source + ")";
  }
  if (!(l.battery_min_in >= travel.battery_min_in - tolerance &&
        l.battery_max_in <= travel.battery_max_in + tolerance)) {
    return "firmware battery limits exceed the vehicle's slide travel (" + setup.source + ")";
  }
  if ((c.plan.waypoint_count > 0 || std::isfinite(c.plan.heading_rad)) && !setup.fitted.rudder) {
    return "the mission steers (waypoints or a heading), but the vehicle has no rudder (fitted.rudder, " +
           setup.source + ")";
  }
  if (c.aborts.remaining_charge_min_pct > 0.0 && !setup.fitted.power_monitor) {
    return "the mission has a low-charge abort, but the vehicle has no power monitor (fitted.power_monitor, " +
           setup.source + ")";
  }
  return "";
}

void load_toml(const std::filesystem::path& path, const FlightSoftwareConfig& base, PreparedMission& out) {
  try {
    const auto doc = config::TomlDocument::load(path);
    FlightSoftwareConfig config = read_flight_config(doc);
    // 0: not given (the SIL's default); at most two years of simulated flight.
    out.sil_max_sim_time_s = doc.number_or("sil.max_sim_time_s", 0.0, {0.0, 2.0 * 366.0 * 86400.0, "s"});
    doc.reject_unknown_keys();
    config.heading = base.heading;
    config.dead_reckoning = base.dead_reckoning;
    out.config = config;
  } catch (const config::ConfigError& error) {
    out.refusal = error.what();
  }
}

}  // namespace

PreparedMission prepare_mission(const std::filesystem::path& mission_path, const VehicleSetup& setup,
                                const MissionOptions& options) {
  PreparedMission out;
  out.slocum = mission_path.extension() == ".mi";
  FlightSoftwareConfig base;
  if (!base_config(setup, options, base, out.refusal)) return out;
  if (out.slocum) {
    mission_file::LoadedMission loaded = mission_file::load_mission_file(mission_path, setup.vehicle, base);
    out.diagnostics = std::move(loaded.diagnostics);
    if (!loaded.config) {
      out.refusal = mission_path.string() + ": mission refused before launch";
      return out;
    }
    out.config = *loaded.config;
    if (options.legs != 0) out.config->plan.legs_to_run = options.legs;
  } else {
    load_toml(mission_path, base, out);
    if (!out.config) return out;
  }
  FlightSoftwareConfig& config = *out.config;
  config.aborts.drop_weight_fitted = setup.fitted.drop_weight;
  std::string problem = check_vehicle(config, setup);
  if (problem.empty()) problem = validate(config);
  if (!problem.empty()) {
    out.refusal = mission_path.string() + ": mission refused: " + problem;
    out.config.reset();
  }
  return out;
}

std::vector<std::string> mission_messages(const PreparedMission& mission, bool errors_only) {
  std::vector<std::string> lines;
  for (const auto& d : mission.diagnostics) {
    if (!errors_only || d.severity == mission_file::Severity::kError) lines.push_back(d.text());
  }
  if (!mission.refusal.empty()) lines.push_back(mission.refusal);
  return lines;
}

}  // namespace glider::fw::app
