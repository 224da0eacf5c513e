// SPDX-License-Identifier: Apache-2.0
// glider-sil: fly a mission in SIL and print a summary. A mission is either
// a Slocum .mi file (with its .ma files; docs/missions.md) or one of the
// project's TOML yo missions (boards/README.md).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/firmware/app/mission_reload.hpp"
#include "glider/firmware/app/mission_setup.hpp"
#include "glider/firmware/log/slocum_directory_sink.hpp"
#include "glider/firmware/log/slocum_list.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/flight_summary.hpp"
#include "glider/sil/glide_check.hpp"
#include "glider/sil/launch_time.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/units.hpp"

namespace {

void print_glides(const char* name, const glider::sil::GlideStats& s) {
  std::printf("  %-7s settled: pitch %6.1f deg, depth rate %+6.3f m/s  (%llu samples, max pitch error %.1f deg)\n",
              name, glider::rad_to_deg(s.mean_pitch_rad()), s.mean_depth_rate_m_s(),
              static_cast<unsigned long long>(s.samples), glider::rad_to_deg(s.max_pitch_error_rad));
}

// All inflection depths for a short mission, their ranges for a long one.
void print_inflections(int yos, const std::vector<double>& depths) {
  std::printf("  yos     : %d flown (inflections at", yos);
  if (depths.size() <= 12) {
    for (double depth : depths) std::printf(" %.1f", depth);
    std::printf(" m)\n");
    return;
  }
  double bottom_min = 1e9, bottom_max = -1e9, top_min = 1e9, top_max = -1e9;
  for (std::size_t i = 0; i < depths.size(); ++i) {
    double& lo = i % 2 == 0 ? bottom_min : top_min;
    double& hi = i % 2 == 0 ? bottom_max : top_max;
    lo = std::min(lo, depths[i]);
    hi = std::max(hi, depths[i]);
  }
  std::printf(" %.1f-%.1f m at the bottoms, %.1f-%.1f m at the tops)\n", bottom_min, bottom_max, top_min, top_max);
}

// DR error at every surfacing (the first dozen and the totals for long runs).
void print_surfacings(const std::vector<glider::sil::SurfacingStats>& surfacings) {
  double error_sum = 0.0, distance_sum = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < surfacings.size(); ++i) {
    const auto& s = surfacings[i];
    error_sum += s.dr_error_m;
    distance_sum += s.dr_distance_m;
    worst = std::max(worst, s.dr_error_m);
    if (i < 12) {
      std::printf(
          "    surfacing %2zu at %8.0f s: DR error %7.1f m over %6.0f m (%5.1f m/km); current %+.3f %+.3f m/s\n", i + 1,
          s.time_s, s.dr_error_m, s.dr_distance_m,
          s.dr_distance_m > 0.0 ? 1000.0 * s.dr_error_m / s.dr_distance_m : 0.0, s.water_vx_m_s, s.water_vy_m_s);
    }
  }
  if (surfacings.size() > 12) std::printf("    ... %zu surfacings in all\n", surfacings.size());
  if (!surfacings.empty()) {
    std::printf("  DR error       : %.1f m/km travelled (sum of errors / sum of DR distances), worst %.1f m\n",
                distance_sum > 0.0 ? 1000.0 * error_sum / distance_sum : 0.0, worst);
  }
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-sil", "Fly a glider mission (.mi Slocum or .toml) in software-in-the-loop simulation");
  CLI::App& app = tool.app();
  std::string vehicle_path;
  std::string summary_json_path;
  std::string mission_path;
  std::string out_path;
  std::string env_path;
  std::uint64_t seed = 1;
  double heading_deg = 90.0;
  double max_working_depth_m = 100.0;
  double max_sim_time_s = 0.0;
  int legs = 0;
  std::string heading_law = "compensated";
  std::string dr_method = "assumed";
  std::vector<std::string> fault_texts;
  double launch_lat = std::nan("");
  double launch_lon = std::nan("");
  bool quiet = false;
  double integration_step_s = glider::model::GliderSimulator::kDefaultStepS;
  tool.add_vehicle_option(vehicle_path);
  app.add_option("--mission,mission", mission_path, "mission file: Slocum .mi, or TOML")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--out", out_path,
                 "flight log to write (CSV, docs/flight-log.md; a name ending in .glb: its binary form, "
                 "several times faster to write, read by every tool, glider-log-info --to-csv converts)");
  app.add_option("--env", env_path, "environment file: water profile, currents, tide (TOML)")->check(CLI::ExistingFile);
  tool.add_integer("--seed", seed, 0, glider::cli::kMaxSeed, "", "seed of the sensor noise")->capture_default_str();
  tool.add_number("--heading-deg", heading_deg, {-360.0, 360.0, "deg"},
                  "initial heading (TOML missions fly it with the fin centred)")
      ->capture_default_str();
  tool.add_number("--max-working-depth-m", max_working_depth_m, {1.0, 11000.0, "m"},
                  ".mi: the vehicle's depth rating (f_max_working_depth)")
      ->capture_default_str();
  tool.add_integer("--legs", legs, -2, 100000, "",
                   ".mi: override goto_list num_legs_to_run (-1 loop, -2 once; a looping list never ends)");
  // 0: the mission's own limit; at most the 60 days a .mi mission may run.
  tool.add_number("--max-sim-time-s", max_sim_time_s, {0.0, 60.0 * 86400.0, "s"},
                  "stop the simulation after this long (default, 0: mission's)");
  app.add_option("--heading-law", heading_law, "fin autopilot: proportional (paper 001), slocum, compensated")
      ->check(CLI::IsMember({"proportional", "slocum", "compensated"}))
      ->capture_default_str();
  app.add_option("--dr", dr_method,
                 "dead reckoning: assumed (constant angle of attack, Slocum) or model (flight model)")
      ->check(CLI::IsMember({"assumed", "model"}))
      ->capture_default_str();
  app.add_option("--fault", fault_texts,
                 "inject NAME@TIME (s, m or h), e.g. leak@1200s; repeatable; "
                 "names: depth_invalid depth_frozen attitude_invalid attitude_frozen "
                 "pump_fault pump_stuck battery_fault fin_fault leak gps_dead power_drain");
  tool.add_number("--launch-lat", launch_lat, {-90.0, 90.0, "deg"},
                  "launch latitude, decimal degrees (default: comet 2019's first fix)");
  tool.add_number("--launch-lon", launch_lon, {-180.0, 180.0, "deg"}, "launch longitude, decimal degrees");
  app.add_flag("--quiet", quiet, "print nothing but errors");
  tool.add_number("--integration-step-s", integration_step_s, {1e-3, 1.0, "s"},
                  "the vehicle model's integration step (accuracy: docs/sil.md, Speed)")
      ->capture_default_str();
  bool check_mission = false;
  std::string slocum_dir;
  std::string sbdlist_path;
  bool slocum_lz4 = false;
  app.add_option("--slocum-dir", slocum_dir,
                 "also write the firmware's Slocum data files (.dbd, .sbd, cac/) into this directory "
                 "(docs/slocum-binary.md, Writing)");
  app.add_option("--sbdlist", sbdlist_path, "the .sbd's sensors and decimation (sbdlist.dat; default: built in)")
      ->check(CLI::ExistingFile);
  app.add_flag("--slocum-lz4", slocum_lz4, "write the Slocum files' LZ4 forms (.dcd, .scd, cac/*.ccc), as a G3S");
  app.add_flag("--check-mission", check_mission, "read the vehicle and the mission, report, exit (nothing flown)");
  app.add_option("--summary-json", summary_json_path,
                 "also write the run's summary as JSON to this file (keys: docs/sil-summary.md)");
  std::string shore_address;
  std::string comms_name;
  std::vector<std::string> dialog_sensors{"m_battery", "m_depth", "m_water_vx", "m_water_vy", "m_coulomb_amphr_total"};
  app.add_option("--shore", shore_address,
                 "call a shore station at every surfacing over the simulated Iridium modem: HOST[:PORT] "
                 "(default port 6565; docs/comms.md)");
  app.add_option("--vehicle-name", comms_name, "the name the vehicle gives in its dialog (default: the vehicle's)");
  app.add_option("--dialog-sensors", dialog_sensors, "log columns in the surface dialog")->delimiter(',');
  std::string launch_utc;
  app.add_option("--launch-utc", launch_utc,
                 "the simulated UTC at launch, YYYY-MM-DDTHH:MM:SSZ (2000..2099; default: now): the Slocum files' "
                 "clock (m_present_time, names, fileopen_time), the dialog's Curr Time");
  double time_scale = 0.0;
  tool.add_number("--time-scale", time_scale, {0.0, 1e6, ""},
                  "at most this many simulated seconds per wall second (0: as fast as it goes); with --shore, "
                  "a pilot or a script has wall time between calls, as in HIL at the same time scale");
  return tool.run(argc, argv, [&]() -> int {
    glider::model::VehicleParams vehicle;
    glider::sil::ScenarioOptions options;
    try {
      vehicle = glider::model::load_vehicle_file(vehicle_path);
      options.fitted = glider::sil::load_fitted_devices(vehicle_path);
      options.environment = env_path.empty() ? glider::model::still_water(vehicle.trim_density_kg_m3)
                                             : glider::model::load_environment_file(env_path);
    } catch (const glider::config::ConfigError& error) {
      return tool.fail(glider::cli::kError, error.what());
    }
    // The flight application's own mission setup, as glider-firmware does it;
    // only where the vehicle data comes from differs (the model here, the board file there).
    glider::fw::app::VehicleSetup setup =
        glider::sil::vehicle_setup(vehicle, options.fitted, max_working_depth_m, dr_method == "model",
                                   options.environment.water.at(0.0, 0.0).density_kg_m3);
    setup.source = vehicle_path;
    glider::fw::app::MissionOptions mission_options;
    mission_options.heading_law = *glider::fw::app::heading_law_from_name(heading_law);
    mission_options.flight_model_dr = dr_method == "model";
    mission_options.legs = legs;
    const glider::fw::app::PreparedMission prepared =
        glider::fw::app::prepare_mission(mission_path, setup, mission_options);
    const std::vector<std::string> messages = glider::fw::app::mission_messages(prepared, quiet);
    for (std::size_t i = 0; i + (prepared.config ? 0 : 1) < messages.size(); ++i) {
      std::fprintf(stderr, "%s\n", messages[i].c_str());
    }
    if (!prepared.config) return tool.fail(glider::cli::kError, prepared.refusal);
    if ((!sbdlist_path.empty() || slocum_lz4) && slocum_dir.empty()) {
      return tool.fail(glider::cli::kUsage, "--sbdlist and --slocum-lz4 need --slocum-dir");
    }
    const glider::fw::SlocumListResult sbdlist =
        sbdlist_path.empty() ? glider::fw::parse_slocum_list(glider::fw::kDefaultSbdList, "built-in sbdlist.dat")
                             : glider::fw::read_slocum_list(sbdlist_path);
    if (!sbdlist.error.empty()) return tool.fail(glider::cli::kError, sbdlist.error);
    if (check_mission) {
      std::fprintf(stderr, "glider-sil: %s: mission accepted for vehicle %s\n", mission_path.c_str(),
                   vehicle.name.c_str());
      return glider::cli::kOk;
    }
    const glider::fw::FlightSoftwareConfig& config = *prepared.config;
    if (prepared.slocum) {
      options.max_sim_time_s = 60.0 * 86400.0;  // the mission's own limits end it
    } else if (prepared.sil_max_sim_time_s > 0.0) {
      options.max_sim_time_s = prepared.sil_max_sim_time_s;
    }
    if (max_sim_time_s > 0.0) options.max_sim_time_s = max_sim_time_s;
    for (const std::string& text : fault_texts) {
      std::string error;
      const auto fault = glider::sil::parse_fault(text, error);
      if (!fault) {
        return tool.fail(glider::cli::kUsage, "--fault: " + error);
      }
      options.faults.push_back(*fault);
    }
    if (std::isfinite(launch_lat) && std::isfinite(launch_lon))
      options.peripherals.gps.launch = {launch_lat, launch_lon};
    options.seed = seed;
    options.integration_step_s = integration_step_s;
    options.heading_deg = heading_deg;
    options.log_path = out_path;
    options.metadata = {
        {"source", "glider SIL (firmware + vehicle model in lockstep)"},
        {"mission_file", std::filesystem::path(mission_path).filename().string()},
        {"vehicle_file", std::filesystem::path(vehicle_path).filename().string()},
        {"environment_file", env_path.empty() ? std::string("none (still water at the vehicle's trim density)")
                                              : std::filesystem::path(env_path).filename().string()},
        {"heading_law", heading_law},
        {"dead_reckoning", dr_method},
        {"time", "m_present_time is seconds since the start of the mission"},
        {"conventions", "Slocum names, units and signs; sim_* are simulator truths"}};

    // The simulated UTC at launch (SIL time 0): as a glider's clock at launch, now unless given.
    std::int64_t launch_utc_s = static_cast<std::int64_t>(
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count());
    if (!launch_utc.empty()) {
      std::string why;
      if (!glider::sil::parse_launch_utc(launch_utc, launch_utc_s, why)) {
        return tool.fail(glider::cli::kUsage, "--launch-utc: value '" + launch_utc + "' " + why);
      }
    }
    if (!slocum_dir.empty()) {
      // The Slocum files' clock is the simulated UTC (a Slocum's m_present_time is Unix seconds);
      // the CSV log keeps the seconds since launch.
      const glider::fw::SlocumMissionNumbers numbers =
          glider::fw::next_slocum_mission(slocum_dir, vehicle.name, launch_utc_s * 1'000'000);
      options.slocum.utc_at_zero_us = launch_utc_s * 1'000'000;
      options.slocum_directory = slocum_dir;
      options.slocum_lz4 = slocum_lz4;
      options.slocum.vehicle = vehicle.name;
      options.slocum.mission_name = std::filesystem::path(mission_path).filename().string();
      options.slocum.mission_of_day = numbers.mission_of_day;
      options.slocum.mission_number = numbers.mission_number;
      options.slocum.sbd = sbdlist.selection;
    }

    std::optional<glider::sil::TcpShore> shore;
    std::optional<glider::fw::app::MissionFileReloader> reloader;
    if (!shore_address.empty()) {
      std::string host, error;
      int port = 0;
      if (!glider::sil::parse_shore_address(shore_address, host, port, error)) {
        return tool.fail(glider::cli::kUsage, "--shore: " + error);
      }
      if (dialog_sensors.size() > glider::fw::comms::kMaxDialogSensors) {
        return tool.fail(glider::cli::kUsage, "--dialog-sensors: at most 16 columns");
      }
      shore.emplace(host, port);
      reloader.emplace(mission_path, setup, mission_options);
      glider::sil::ScenarioOptions::Comms& c = options.comms.emplace();
      std::snprintf(c.config.vehicle_name, sizeof c.config.vehicle_name, "%s",
                    comms_name.empty() ? vehicle.name.c_str() : comms_name.c_str());
      // The simulated modem connects any number to --shore (RUDICS: the call is a TCP connection).
      std::snprintf(c.config.primary_number, sizeof c.config.primary_number, "0088160000519");
      std::snprintf(c.config.mission_name, sizeof c.config.mission_name, "%s",
                    std::filesystem::path(mission_path).filename().string().c_str());
      for (const std::string& name : dialog_sensors) {
        std::snprintf(c.config.sensors[c.config.sensor_count++].data(), glider::fw::comms::kTextField, "%s",
                      name.c_str());
      }
      c.far_end = &*shore;
      c.reloader = &*reloader;
      c.utc_at_launch_s = static_cast<double>(launch_utc_s);
    }
    if (time_scale > 0.0) {
      const auto paced_from = std::chrono::steady_clock::now();
      options.before_cycle = [paced_from, time_scale](double sim_time_s, glider::sil::SimHal&) {
        std::this_thread::sleep_until(paced_from + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                       std::chrono::duration<double>(sim_time_s / time_scale)));
      };
    }
    const auto wall_start = std::chrono::steady_clock::now();
    const glider::sil::ScenarioResult result = glider::sil::run_scenario(vehicle, config, options);
    const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

    if (!result.error.empty()) return tool.fail(glider::cli::kError, result.error);
    // Even with --quiet: a flight the vehicle cannot make is not a result to use unwarned.
    const std::vector<std::string> glide_warnings = glider::sil::unflyable_glide_warnings(
        vehicle.hydro, options.environment.water.at(0.0, 0.0).density_kg_m3, result.stats);
    for (const std::string& warning : glide_warnings)
      std::fprintf(stderr, "glider-sil: warning: %s\n", warning.c_str());
    if (!summary_json_path.empty()) {
      glider::sil::SummaryContext context;
      context.mission_file = mission_path;
      context.vehicle_file = vehicle_path;
      context.seed = seed;
      context.wall_time_s = wall_s;
      context.launch = options.peripherals.gps.launch;
      context.glide_warnings = glide_warnings;
      std::ofstream json(summary_json_path, std::ios::out | std::ios::trunc);
      json << glider::sil::flight_summary(result, config, context).dump(2) << '\n';
      json.close();
      if (!json) return tool.fail(glider::cli::kError, summary_json_path + ": cannot write the summary");
    }
    const bool aborted = result.final_phase == glider::fw::Phase::kAbort;
    if (!quiet) {
      const auto& stats = result.stats;
      std::printf("SIL flight: %s with vehicle %s (seed %llu)\n", mission_path.c_str(), vehicle.name.c_str(),
                  static_cast<unsigned long long>(seed));
      if (aborted) {
        std::printf("  result  : ABORTED (%s) at %.0f s", glider::fw::to_string(result.abort_cause),
                    result.abort_time_s);
        if (result.abort_surfaced_s >= 0.0) {
          std::printf(", at the surface %.0f s later (truth: antenna out)",
                      result.abort_surfaced_s - result.abort_time_s);
        } else {
          std::printf(", NOT at the surface");
        }
        std::printf("%s%s\n",
                    result.completed ? "; the firmware knows it is up" : "; the firmware cannot tell it is up",
                    result.drop_weight_released ? "; drop weight released" : "");
      } else {
        std::printf("  result  : %s\n", result.completed ? "mission complete, surfaced" : "NOT complete (time limit)");
      }
      print_inflections(result.yos, stats.inflection_depths_m());
      print_glides("dives", stats.dives());
      print_glides("climbs", stats.climbs());
      if (config.plan.waypoint_count > 0 || stats.segments() > 1) {
        std::printf("  segments       : %d; waypoints reached %d (of a list of %d)\n", stats.segments(),
                    stats.waypoints_reached(), config.plan.waypoint_count);
        const glider::fw::LocalFrame frame(options.peripherals.gps.launch);
        for (const auto& w : result.waypoints) {
          const auto index = static_cast<std::size_t>((w.reached - 1) % config.plan.waypoint_count);
          const glider::fw::EastNorth target = frame.to_local(config.plan.waypoints[index]);
          std::printf("    waypoint %zu counted at %8.0f s, true distance %6.0f m (radius %.0f m)\n", index, w.time_s,
                      std::hypot(w.east_m - target.east_m, w.north_m - target.north_m), config.plan.waypoint_radius_m);
        }
      }
      print_surfacings(stats.surfacings());
      std::printf("  distance       : %.2f km over ground (start to end)\n",
                  std::hypot(result.final_truth.east_m, result.final_truth.north_m) / 1000.0);
      std::printf("  energy         : %.0f kJ, %.2f Ah\n", result.energy_used_j / 1000.0, result.charge_used_amphr);
      if (result.sim_time_s < 86400.0) {
        std::printf("  simulated time : %.0f s (%.1f min)\n", result.sim_time_s, result.sim_time_s / 60.0);
      } else {
        std::printf("  simulated time : %.0f s (%.1f days)\n", result.sim_time_s, result.sim_time_s / 86400.0);
      }
      if (options.comms) {
        const auto& c = result.comms;
        std::printf(
            "  comms          : %u surfacings, %u calls connected (%u dialled), %u without a call, %u drops; "
            "%llu bytes up, %llu down\n",
            c.surfacings, c.calls_connected, c.dial_attempts, c.surfacings_without_call, c.carrier_drops,
            static_cast<unsigned long long>(result.modem.bytes_up),
            static_cast<unsigned long long>(result.modem.bytes_down));
        if (shore) {
          std::printf("  shore pacing   : %u waits for the shore's answer, %u unanswered within %d ms\n",
                      shore->waits(), shore->unanswered_waits(), glider::sil::TcpShore::kDefaultAnswerWaitMs);
        }
      }
      std::printf("  wall time      : %.4f s\n", wall_s);
      std::printf("  real-time factor: %.0fx\n", wall_s > 0.0 ? result.sim_time_s / wall_s : 0.0);
      std::printf("  loop overruns  : %u (cycles %llu)\n", result.executive.overruns,
                  static_cast<unsigned long long>(result.executive.cycles));
      if (!out_path.empty()) {
        std::printf("  flight log     : %s (%llu rows)\n", out_path.c_str(),
                    static_cast<unsigned long long>(result.log_rows));
      }
      if (!slocum_dir.empty()) {
        const std::uint64_t slocum_lost = result.slocum_dbd.cycles_lost + result.slocum_sbd.cycles_lost;
        std::printf(
            "  slocum files   : %s (%d segments; .dbd %llu cycles, .sbd %llu cycles, %llu lost, "
            "%llu values not representable)\n",
            slocum_dir.c_str(), result.slocum_segments,
            static_cast<unsigned long long>(result.slocum_dbd.cycles_written),
            static_cast<unsigned long long>(result.slocum_sbd.cycles_written),
            static_cast<unsigned long long>(slocum_lost),
            static_cast<unsigned long long>(result.slocum_unrepresentable));
      }
    }
    // Aborted, or stopped by the time limit before the mission ended.
    return !aborted && result.completed ? glider::cli::kOk : glider::cli::kStopped;
  });
}
