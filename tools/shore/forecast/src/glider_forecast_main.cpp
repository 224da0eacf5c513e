// SPDX-License-Identifier: Apache-2.0
// glider-forecast: where a glider surfaces next, from the shore's glider
// folder, and the rehearsal of a .ma/.mi before it is sent (docs/forecast.md).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider/forecast/tide_fit.hpp"

namespace {

// fit-tide: the constituents of a glider folder's depth-averaged currents
// (its surfacings' m_water_vx/vy), those whose segment overlaps
// [exclude_from, exclude_to] left out, written as a tide table.
int fit_tide_command(const std::string& glider_dir, const std::vector<std::string>& names,
                     const std::string& exclude_from, const std::string& exclude_to, const std::string& out) {
  namespace fc = glider::forecast;
  const std::vector<fc::Surfacing> history = fc::read_surfacings(glider_dir);
  // The first event's estimate is over the segment before the history: as long as the median later one.
  std::vector<double> spans;
  for (const fc::CurrentSample& s : fc::current_samples(history, 1.0, 0.0)) {
    if (s.span_s > 0.0) spans.push_back(s.span_s);
  }
  std::sort(spans.begin(), spans.end());
  const double first_span = spans.empty() ? 0.0 : spans[spans.size() / 2];
  const double lo = exclude_from.empty() ? 0.0 : fc::parse_utc(exclude_from, "--exclude-from");
  const double hi = exclude_to.empty() ? 0.0 : fc::parse_utc(exclude_to, "--exclude-to");
  std::vector<fc::CurrentSample> used;
  int left_out = 0;
  for (const fc::CurrentSample& s : fc::current_samples(history, 1.0, first_span)) {
    const bool overlaps = !exclude_from.empty() && s.utc_s + 0.5 * s.span_s > lo && s.utc_s - 0.5 * s.span_s < hi;
    if (overlaps) {
      ++left_out;
    } else {
      used.push_back(s);
    }
  }
  if (used.empty()) throw std::runtime_error(glider_dir + ": no depth-averaged current (m_water_vx/vy) to fit");
  // The phases' origin: the hour at or before the first segment's start.
  const double reference = std::floor((used.front().utc_s - 0.5 * used.front().span_s) / 3600.0) * 3600.0;
  const fc::TideFit fit = fc::fit_tide(used, names, reference);
  char text[400];
  std::snprintf(text, sizeof text,
                "glider forecast fit-tide --glider-dir %s: %d estimates over %.1f h (%d left out), residual RMS "
                "%.3f E %.3f N m/s;\nthe sigmas are the fit's (1 sigma, the larger of east's and north's): the "
                "record's tide, not the year's",
                glider_dir.c_str(), fit.estimates, fit.record_s / 3600.0, left_out, fit.residual_east_m_s,
                fit.residual_north_m_s);
  const std::string table = fc::format_tide_table(fit.table, text);
  if (out.empty()) {
    std::printf("%s", table.c_str());
  } else {
    std::ofstream file(out);
    file << table;
    if (!file) throw std::runtime_error(out + ": cannot write");
  }
  for (const fc::TideConstituent& c : fit.table.constituents) {
    std::fprintf(stderr,
                 "%s: east %.3f m/s (95 %% %.3f-%.3f) phase %.0f +- %.0f deg; north %.3f m/s (95 %% %.3f-%.3f) phase "
                 "%.0f +- %.0f deg\n",
                 c.name.c_str(), c.east.amplitude_m_s, c.east.amplitude_m_s - fit.t95 * c.east.amplitude_sigma_m_s,
                 c.east.amplitude_m_s + fit.t95 * c.east.amplitude_sigma_m_s, c.east.phase_deg,
                 fit.t95 * c.east.phase_sigma_deg, c.north.amplitude_m_s,
                 c.north.amplitude_m_s - fit.t95 * c.north.amplitude_sigma_m_s,
                 c.north.amplitude_m_s + fit.t95 * c.north.amplitude_sigma_m_s, c.north.phase_deg,
                 fit.t95 * c.north.phase_sigma_deg);
  }
  return 0;
}

}  // namespace

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
  std::string tide_table;
  auto common = [&](CLI::App* command) {
    command->add_option("--tide", tide_table,
                        "the pilot's tidal constituents for the place (a TOML tide table: docs/forecast.md, session "
                        "44; `fit-tide` writes one): the tide's phase the first forecasts cannot know");
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
  CLI::App* fit = app.add_subcommand(
      "fit-tide", "fit tidal constituents to a glider folder's depth-averaged currents, written as a tide table");
  std::vector<std::string> constituents{"M2"};
  std::string exclude_from, exclude_to, fit_out;
  fit->add_option("--glider-dir", glider_dir, "the shore's folder of the glider (ROOT/GLIDER); required");
  fit->add_option("--constituents", constituents, "the constituents (M2, S2, N2, K2, K1, O1, P1, Q1, M4)")
      ->delimiter(',')
      ->capture_default_str();
  fit->add_option("--exclude-from", exclude_from, "leave out the estimates whose segment overlaps from this UTC...");
  fit->add_option("--exclude-to", exclude_to, "... to this UTC (YYYY-MM-DDTHH:MM:SSZ)");
  fit->add_option("--out", fit_out, "the table's file (default: standard output)");
  app.require_subcommand(0, 1);
  return tool.run(argc, argv, [&]() -> int {
    if (glider_dir.empty()) throw glider::cli::ToolError(glider::cli::kUsage, "--glider-dir is required");
    if (*fit) {
      if (exclude_from.empty() != exclude_to.empty()) {
        throw glider::cli::ToolError(glider::cli::kUsage, "--exclude-from and --exclude-to go together");
      }
      return fit_tide_command(glider_dir, constituents, exclude_from, exclude_to, fit_out);
    }
    options.tide_table = tide_table;
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
