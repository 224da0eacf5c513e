// glider-sil: fly a mission in SIL and print a summary.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/vehicle_file.hpp"
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

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Fly a glider mission in software-in-the-loop simulation"};
  std::string vehicle_path;
  std::string mission_path;
  std::string out_path;
  std::string env_path;
  std::uint64_t seed = 1;
  double heading_deg = 90.0;
  bool quiet = false;
  app.add_option("--vehicle", vehicle_path, "vehicle parameter file (TOML)")->required()->check(CLI::ExistingFile);
  app.add_option("--mission", mission_path, "mission file (TOML)")->required()->check(CLI::ExistingFile);
  app.add_option("--out", out_path, "flight log to write (CSV, docs/flight-log.md)");
  app.add_option("--env", env_path, "environment file: water profile, currents, tide (TOML)")->check(CLI::ExistingFile);
  app.add_option("--seed", seed, "seed of the sensor noise")->capture_default_str();
  app.add_option("--heading-deg", heading_deg, "heading to fly")->capture_default_str();
  app.add_flag("--quiet", quiet, "print nothing but errors");
  CLI11_PARSE(app, argc, argv);

  glider::model::VehicleParams vehicle;
  glider::fw::FlightSoftwareConfig config;
  glider::sil::ScenarioOptions options;
  try {
    vehicle = glider::model::load_vehicle_file(vehicle_path);
    options.environment = env_path.empty() ? glider::model::still_water(vehicle.trim_density_kg_m3)
                                           : glider::model::load_environment_file(env_path);
    const auto mission = glider::config::TomlDocument::load(mission_path);
    config = glider::fw::read_flight_config(mission);
    options.max_sim_time_s = mission.number_or("sil.max_sim_time_s", options.max_sim_time_s);
    mission.reject_unknown_keys();
  } catch (const glider::config::ConfigError& error) {
    std::fprintf(stderr, "glider-sil: %s\n", error.what());
    return 1;
  }
  options.seed = seed;
  options.heading_deg = heading_deg;
  options.log_path = out_path;
  options.metadata = {{"source", "glider SIL (firmware + vehicle model in lockstep)"},
                      {"mission_file", std::filesystem::path(mission_path).filename().string()},
                      {"vehicle_file", std::filesystem::path(vehicle_path).filename().string()},
                      {"environment_file", env_path.empty() ? std::string("none (still water at the vehicle's trim density)")
                                                            : std::filesystem::path(env_path).filename().string()},
                      {"time", "m_present_time is seconds since the start of the mission"},
                      {"conventions", "Slocum names, units and signs; sim_* are simulator truths"}};

  const auto wall_start = std::chrono::steady_clock::now();
  const glider::sil::ScenarioResult result = glider::sil::run_scenario(vehicle, config, options);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  if (!result.error.empty()) {
    std::fprintf(stderr, "glider-sil: %s\n", result.error.c_str());
    return 1;
  }
  const bool aborted = result.final_phase == glider::fw::Phase::kAbort;
  if (!quiet) {
    std::printf("SIL flight: %s with vehicle %s (seed %llu)\n", mission_path.c_str(), vehicle.name.c_str(),
                static_cast<unsigned long long>(seed));
    if (aborted) {
      std::printf("  result  : ABORTED (%s)%s\n", glider::fw::to_string(result.abort_cause),
                  result.completed ? ", surfaced" : "");
    } else {
      std::printf("  result  : %s\n", result.completed ? "mission complete, surfaced" : "NOT complete (time limit)");
    }
    print_inflections(result.yos, result.stats.inflection_depths_m());
    print_glides("dives", result.stats.dives());
    print_glides("climbs", result.stats.climbs());
    std::printf("  distance       : %.2f km over ground\n",
                std::hypot(result.final_truth.east_m, result.final_truth.north_m) / 1000.0);
    if (result.sim_time_s < 86400.0) {
      std::printf("  simulated time : %.0f s (%.1f min)\n", result.sim_time_s, result.sim_time_s / 60.0);
    } else {
      std::printf("  simulated time : %.0f s (%.1f days)\n", result.sim_time_s, result.sim_time_s / 86400.0);
    }
    std::printf("  wall time      : %.4f s\n", wall_s);
    std::printf("  real-time factor: %.0fx\n", wall_s > 0.0 ? result.sim_time_s / wall_s : 0.0);
    std::printf("  loop overruns  : %u (cycles %llu)\n", result.executive.overruns,
                static_cast<unsigned long long>(result.executive.cycles));
    if (!out_path.empty()) {
      std::printf("  flight log     : %s (%llu rows)\n", out_path.c_str(),
                  static_cast<unsigned long long>(result.log_rows));
    }
  }
  if (aborted) return 2;
  return result.completed ? 0 : 3;
}
