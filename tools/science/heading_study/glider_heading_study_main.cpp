// SPDX-License-Identifier: Apache-2.0
// glider-heading-study: the heading autopilot in SIL against the real
// comet logs (docs/heading-control.md). Measures the real gliders' heading
// oscillation and roll-offset error, then flies the same vehicle in SIL with
// paper 001's P law and Slocum's law while the fin's dead time grows, and
// the compensated law on the worst case. Prints one line per case.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/firmware/app/mission_setup.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/slocum/log_loader.hpp"
#include "glider/units.hpp"
#include "heading_metrics.hpp"
#include "heading_replay.hpp"
#include "unseen_table.hpp"

namespace {

using glider::heading_study::HeadingMetrics;

struct Case {
  std::string name;
  glider::fw::HeadingLaw law;
  double roll_deg;
  double delay_s;
};

const char* law_name(glider::fw::HeadingLaw law) {
  switch (law) {
    case glider::fw::HeadingLaw::kProportional:
      return "P (paper 001, kp 0.5)";
    case glider::fw::HeadingLaw::kSlocum:
      return "Slocum (1.5, 0.02, -4)";
    case glider::fw::HeadingLaw::kCompensated:
      return "compensated";
  }
  return "?";
}

// Flies the heading-hold mission; nullopt-like empty name on failure.
bool fly(const std::string& source, const std::string& out_dir, const Case& c, HeadingMetrics& metrics) {
  const std::string vehicle_path = source + "/boards/vehicles/slocum_comet.toml";
  glider::model::VehicleParams vehicle = glider::model::load_vehicle_file(vehicle_path);
  vehicle.heading.roll_offset_rad = glider::deg_to_rad(c.roll_deg);
  vehicle.heading.fin_delay_s = c.delay_s;  // the compensated law is told the fin's dead time (bench-measured)
  // The mission as glider-sil prepares it: the vehicle setup from the model, then the
  // flight application's one mission entry (fw::app::prepare_mission).
  glider::sil::ScenarioOptions options;
  options.fitted = glider::sil::load_fitted_devices(vehicle_path);
  const glider::fw::app::VehicleSetup setup = glider::sil::vehicle_setup(
      vehicle, options.fitted, 102.0, false, options.environment.water.at(0.0, 0.0).density_kg_m3);
  glider::fw::app::MissionOptions mission_options;
  mission_options.heading_law = c.law;
  const glider::fw::app::PreparedMission prepared =
      glider::fw::app::prepare_mission(source + "/boards/missions/heading_hold.mi", setup, mission_options);
  if (!prepared.config) {
    for (const std::string& line : glider::fw::app::mission_messages(prepared, true)) {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
    return false;
  }
  options.log_path = out_dir + "/" + c.name + ".csv";
  const glider::sil::ScenarioResult r = glider::sil::run_scenario(vehicle, *prepared.config, options);
  if (!r.error.empty() || !r.completed) {
    std::fprintf(stderr, "glider-heading-study: %s: %s\n", c.name.c_str(),
                 r.error.empty() ? "mission did not complete" : r.error.c_str());
    return false;
  }
  metrics = glider::heading_study::heading_metrics(glider::flightlog::read_flight_log(options.log_path), 900.0);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool(
      "glider-heading-study",
      "Heading autopilot study: real comet logs vs SIL with fin dead time, before and after the fix");
  CLI::App& app = tool.app();
  std::string source = ".";
  std::string out_dir = "build/heading_study";
  std::vector<double> delays{0.0, 5.0, 10.0, 15.0, 20.0};
  app.add_option("--source", source, "repository root (boards/, tests/data/real)")->capture_default_str();
  app.add_option("--out", out_dir, "where the SIL logs go")->capture_default_str();
  tool.add_numbers("--delays", delays, {0.0, 600.0, "s"}, "fin dead times to fly (s)")->capture_default_str();
  bool replay_only = false;
  app.add_flag("--replay-only", replay_only,
               "only the replay: each real log's identified heading loop (glider-diagnose) flown in SIL");
  glider::heading_study::ReplayOptions replay_options;
  bool nominal_speed = false;
  app.add_flag("--nominal-speed", nominal_speed,
               "replay: at the nominal vehicle's speed (by default its lift and drag are scaled and its buoyancy "
               "offset so it glides at the log's speeds through the water)");
  bool no_disturbance = false;
  app.add_flag("--no-disturbance", no_disturbance, "replay: without the calibrated random yaw (compass noise only)");
  tool.add_integer("--seed", replay_options.seed, 0, glider::cli::kMaxSeed, "",
                   "replay: the SIL runs' seed (compass noise, random yaw)")
      ->capture_default_str();
  tool.add_number("--step", replay_options.integration_step_s, {0.01, 1.0, "s"},
                  "replay: the plant's integration step (s)")
      ->capture_default_str();
  bool no_shear = false;
  app.add_flag("--no-shear", no_shear, "replay: in still water (without the identified shear of the current)");
  std::vector<std::string> real_logs;
  app.add_option("--real", real_logs,
                 "real logs to measure instead of the three comet CSVs: a CSV, or a directory / glob of a glider's "
                 "binary files (repeatable)");
  std::string unseen_table;
  app.add_option("--unseen-table", unseen_table,
                 "only the replay out of sample: each comet-2019 log's identified loop predicting the other's steady "
                 "errors, in each log's water; the markdown table written to this file "
                 "(docs/diagnose/heading-replay-unseen.md, which sil.HeadingReplayUnseen checks)");
  return tool.run(argc, argv, [&] {
    std::filesystem::create_directories(out_dir);
    if (!unseen_table.empty()) {
      std::string table = glider::heading_study::table_header();
      for (const auto& c : glider::heading_study::unseen_cases()) {
        table += glider::heading_study::table_row(glider::heading_study::predict_unseen(source, c, out_dir));
      }
      std::ofstream(unseen_table) << table;
      std::printf("%s", table.c_str());
      return glider::cli::kOk;
    }
    replay_options.yaw_disturbance = !no_disturbance;
    replay_options.match_speed = !nominal_speed;
    replay_options.current_shear = !no_shear;

    glider::flightlog::ReadOptions real;
    real.columns = {"m_heading", "c_heading", "m_depth_state", "c_fin", "m_pitch", "m_roll"};
    std::printf("Real comet logs (glides with a heading command):\n");
    if (real_logs.empty()) {
      for (const char* log : {"comet-2016-174-05", "comet-2019-222-02-154", "comet-2019-222-02-156"}) {
        real_logs.push_back(source + "/tests/data/real/" + log + ".csv");
      }
    }
    for (const std::string& log : real_logs) {
      std::vector<glider::slocum::Warning> warnings;
      const auto data = glider::slocum::load_flight_log({{log}, {}}, real, &warnings);
      for (const auto& w : warnings) std::fprintf(stderr, "glider-heading-study: warning: %s\n", w.text().c_str());
      const HeadingMetrics m = glider::heading_study::heading_metrics(data, 0.0);
      std::printf("  %-24s %s\n  %-24s %s\n", std::filesystem::path(log).stem().c_str(),
                  glider::heading_study::format(m).c_str(), "", glider::heading_study::format_inflections(m).c_str());
    }

    int failures = 0;
    std::printf(
        "SIL replay of each log's identified loop (glider-diagnose --plane heading from slocum_comet; 4 s cycle; the "
        "loop's dead time at the fin; the identified shear of the current):\n");
    for (const std::string& log : real_logs) {
      try {
        const auto r = glider::heading_study::replay_log(source, log, source + "/boards/vehicles/slocum_comet.toml",
                                                         out_dir, replay_options);
        const auto& v = r.identified.values;
        using glider::diagnose::HeadingEffect;
        std::printf(
            "  %s: identified gain %.3f, igain %.2g, dgain %.2f, deadband %.1f deg, loop dead time %.1f s, fin gain "
            "x%.2f, roll %+.1f deg; compass jitter %.2f deg, yaw disturbance %.2f deg/s over %.0f s\n"
            "    speed through the water dive/climb: log %.3f/%.3f m/s, nominal vehicle in SIL %.3f/%.3f, replay "
            "%.3f/%.3f (lift and drag x%.2f, buoyancy offset %+.0f g)\n"
            "    real             %s\n    SIL, identified  %s\n    SIL, compensated %s\n"
            "    real             %s\n    SIL, identified  %s\n",
            std::filesystem::path(log).stem().c_str(), glider::diagnose::at(v, HeadingEffect::kAutopilotGain),
            glider::diagnose::at(v, HeadingEffect::kAutopilotIntegral),
            glider::diagnose::at(v, HeadingEffect::kAutopilotDgain),
            glider::rad_to_deg(glider::diagnose::at(v, HeadingEffect::kAutopilotDeadband)), r.loop_delay_s,
            glider::diagnose::at(v, HeadingEffect::kFinEffectiveness),
            glider::rad_to_deg(r.identified.logged_roll_rad + glider::diagnose::at(v, HeadingEffect::kRollOffset)),
            glider::rad_to_deg(r.identified.heading_noise_rad), glider::rad_to_deg(r.yaw_disturbance_rad_s),
            r.yaw_disturbance_correlation_s, r.log_speed.dive, r.log_speed.climb, r.nominal_speed.dive,
            r.nominal_speed.climb, r.sil_speed.dive, r.sil_speed.climb, r.area_scale, 1e3 * r.buoyancy_offset_kg,
            glider::heading_study::format(r.real).c_str(), glider::heading_study::format(r.sil_identified).c_str(),
            glider::heading_study::format(r.sil_compensated).c_str(),
            glider::heading_study::format_inflections(r.real).c_str(),
            glider::heading_study::format_inflections(r.sil_identified).c_str());
      } catch (const std::exception& e) {
        std::fprintf(stderr, "glider-heading-study: replay of %s: %s\n", log.c_str(), e.what());
        ++failures;
      }
    }
    if (replay_only) return failures == 0 ? glider::cli::kOk : glider::cli::kError;
    auto run = [&](const Case& c) {
      HeadingMetrics m;
      if (!fly(source, out_dir, c, m)) {
        ++failures;
        return;
      }
      std::printf("  %-24s roll %+5.1f deg, fin dead time %4.1f s: %s\n", law_name(c.law), c.roll_deg, c.delay_s,
                  glider::heading_study::format(m).c_str());
    };
    std::printf("SIL, comet vehicle, roll +3.7 deg (comet 2016), fin 0.1 rad/s:\n");
    for (const double delay : delays) {
      for (const auto law : {glider::fw::HeadingLaw::kProportional, glider::fw::HeadingLaw::kSlocum,
                             glider::fw::HeadingLaw::kCompensated}) {
        char name[64];
        std::snprintf(name, sizeof(name), "roll4_law%d_delay%02.0f", static_cast<int>(law), delay);
        run({name, law, 3.7, delay});
      }
    }
    std::printf("SIL, comet vehicle, roll -10 deg (comet 2019), fin 0.1 rad/s:\n");
    for (const double delay : {0.0, delays.back()}) {
      for (const auto law : {glider::fw::HeadingLaw::kProportional, glider::fw::HeadingLaw::kSlocum,
                             glider::fw::HeadingLaw::kCompensated}) {
        char name[64];
        std::snprintf(name, sizeof(name), "roll10_law%d_delay%02.0f", static_cast<int>(law), delay);
        run({name, law, -10.0, delay});
      }
    }
    return failures == 0 ? glider::cli::kOk : glider::cli::kError;
  });
}
