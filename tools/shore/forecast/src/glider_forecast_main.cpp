// SPDX-License-Identifier: Apache-2.0
// glider-forecast: where a glider surfaces next, from the shore's glider
// folder, and the rehearsal of a .ma/.mi before it is sent (docs/forecast.md).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/forecast/forecast.hpp"

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-forecast",
                         "next surfacing forecast (SIL Monte-Carlo from the last fix) and rehearsal of a .ma/.mi");
  CLI::App& app = tool.app();
  glider::forecast::ForecastOptions options;
  std::string glider_dir;
  bool json = false;
  std::string prior_mode;
  double prior_mean = 0.10, prior_m2 = 0.25, prior_estimate = 0.02, prior_position = 100.0;
  std::vector<std::pair<CLI::Option*, int>> prior_options;  // 0 mean, 1 M2, 2 estimate, 3 position
  auto common = [&](CLI::App* command) {
    command->add_option("--glider-dir", glider_dir, "the shore's folder of the glider (ROOT/GLIDER); required");
    command->add_option("--mission", options.mission,
                        "the glider's .mi (default: GLIDER/mission/missions/NAME.mi, its .ma in mission/mafiles/)");
    command->add_option("--vehicle", options.vehicle,
                        "vehicle file (default: GLIDER/health/vehicle.toml, else boards/gliders.toml's)");
    tool.add_integer(command, "--runs", options.runs, 1, 100000, "runs", "Monte-Carlo runs")->capture_default_str();
    tool.add_integer(command, "--threads", options.threads, 1, 64, "threads", "threads (the runs are split)")
        ->capture_default_str();
    tool.add_integer(command, "--seed", options.seed, 0, glider::cli::kMaxSeed, "", "first run's seed")
        ->capture_default_str();
    tool.add_integer(command, "--waypoint", options.waypoint, -1, 31, "index",
                     "the waypoint the glider flies to now (default -1: replayed from the surfacings)")
        ->capture_default_str();
    tool.add_number(command, "--max-working-depth-m", options.max_working_depth_m, {1.0, 11000.0, "m"},
                    "the glider's rating the mission is checked against")
        ->capture_default_str();
    command->add_flag(
        "--speed-correction", options.speed_correction,
        "scale the model's drag to the glider's dead-reckoned speed through the water even without its pitch "
        "sensor's calibration (default: only with it; docs/forecast.md)");
    command->add_flag("!--no-speed-correction", options.speed_correction_calibrated,
                      "never scale the model's drag to the glider's speed");
    command->add_flag("!--no-glider-dead-reckoning", options.glider_dead_reckoning,
                      "the model's firmware dead-reckons as the vehicle file's, not through the glider's pitch sensor "
                      "(docs/forecast.md)");
    command->add_flag("!--no-depth-rate-calibration", options.depth_rate_calibration,
                      "fly the model as the vehicle file says, not calibrated to the glider's steady-glide depth "
                      "rates read from from-glider/ (docs/forecast.md)");
    command->add_flag("--depth-rate-drag", options.depth_rate_drag,
                      "with the battery fixed, fly the drag and buoyancy the depth rates read too (default: said, "
                      "not flown; under the pitch servo the calibration is flown; docs/forecast.md)");
    command->add_flag("--pitch-calibration", options.pitch_calibration,
                      "calibrate the glider's dead-reckoned speed for its pitch sensor's scale read from from-glider/ "
                      "(then the drag is corrected and the model dead-reckons as the glider; off by default: the "
                      "real comet contradicts it, docs/forecast.md)");
    command
        ->add_option("--current-prior", prior_mode,
                     "the current's prior: evidence (the estimates weigh its widths), fixed or off (persistence); "
                     "default: GLIDER/forecast.toml's, else evidence")
        ->check(CLI::IsMember({"evidence", "fixed", "off"}));
    prior_options.emplace_back(tool.add_number(command, "--prior-mean-sigma", prior_mean, {0.0, 2.0, "m/s"},
                                               "the prior's mean current, 1 sigma per component (default 0.10)"),
                               0);
    prior_options.emplace_back(tool.add_number(command, "--prior-m2-sigma", prior_m2, {0.0, 2.0, "m/s"},
                                               "the prior's M2 tide coefficients, 1 sigma (default 0.25)"),
                               1);
    prior_options.emplace_back(tool.add_number(command, "--prior-estimate-sigma", prior_estimate, {0.001, 1.0, "m/s"},
                                               "each current estimate's own error, 1 sigma (default 0.02)"),
                               2);
    prior_options.emplace_back(
        tool.add_number(command, "--prior-position-sigma", prior_position, {0.0, 5000.0, "m"},
                        "each current estimate's position error over its segment, 1 sigma per axis (default 100; 0: "
                        "a short segment's estimate no noisier than a long one's)"),
        3);
  };
  common(&app);
  tool.add_json_flag(json);
  CLI::App* rehearse = app.add_subcommand("rehearse", "fly a .ma/.mi as if sent: exit 0 ok, 1 refused, 4 aborts");
  std::string file;
  rehearse->add_option("FILE", file, "the .ma or .mi to rehearse")->required();
  rehearse->add_flag("--json", json, "JSON instead of text");
  common(rehearse);
  app.require_subcommand(0, 1);
  return tool.run(argc, argv, [&]() -> int {
    if (glider_dir.empty()) throw glider::cli::ToolError(glider::cli::kUsage, "--glider-dir is required");
    if (!prior_mode.empty()) options.prior.mode = glider::forecast::parse_prior_mode(prior_mode);
    for (const auto& [option, which] : prior_options) {
      if (option->count() == 0) continue;
      if (which == 0) options.prior.mean_sigma_m_s = prior_mean;
      if (which == 1) options.prior.m2_sigma_m_s = prior_m2;
      if (which == 2) options.prior.estimate_sigma_m_s = prior_estimate;
      if (which == 3) options.prior.position_sigma_m = prior_position;
    }
    if (*rehearse) {
      const glider::forecast::Rehearsal r = glider::forecast::rehearse(glider_dir, file, options);
      if (json) {
        std::printf("%s\n", glider::forecast::rehearsal_json(r, r.forecast.glider).dump(2).c_str());
      } else {
        std::printf("rehearsal of %s: %s: %s\n%s", r.file.c_str(), r.verdict.c_str(), r.message.c_str(),
                    glider::forecast::forecast_text(r.forecast).c_str());
      }
      return glider::forecast::rehearsal_exit_code(r);
    }
    const glider::forecast::Forecast f = glider::forecast::make_forecast(glider_dir, options);
    if (json) {
      std::printf("%s\n", glider::forecast::forecast_json(f).dump(2).c_str());
    } else {
      std::printf("%s", glider::forecast::forecast_text(f).c_str());
    }
    return f.refusal.empty() ? 0 : 1;
  });
}
