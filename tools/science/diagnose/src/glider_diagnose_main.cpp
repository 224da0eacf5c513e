// SPDX-License-Identifier: Apache-2.0
// glider-diagnose: what the simulation gets wrong in a flight log, the named
// cause, the fitted effect and the gain on held-out yos.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "glider/cli/tool.hpp"
#include "glider/config/toml_document.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/diagnosis_json.hpp"
#include "glider/diagnose/heading_report.hpp"
#include "glider/diagnose/pitch_calibration.hpp"
#include "glider/diagnose/stored_on_change.hpp"
#include "glider/diagnose/tool_inputs.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/report/report.hpp"
#include "glider/slocum/deployment.hpp"
#include "glider/slocum/log_loader.hpp"
#include "glider/units.hpp"

namespace {

using glider::diagnose::Diagnosis;
using glider::diagnose::Effect;
using glider::diagnose::info;
using nlohmann::ordered_json;

ordered_json to_json(const Diagnosis& d, const std::string& vehicle_source, double wall_s) {
  return glider::diagnose::diagnosis_json(d, vehicle_source, wall_s);
}

// The yo the extended model's speed misses most, and the RMS without it.
void print_worst_yo(const glider::diagnose::SpeedScore& u) {
  if (u.by_yo.size() < 2) return;
  const auto worst = std::max_element(u.by_yo.begin(), u.by_yo.end(), [](const auto& a, const auto& b) {
    return a.extended_rms_m_s < b.extended_rms_m_s;
  });
  // RMS over the other yos (all, held out) from each yo's RMS and count.
  auto without_worst = [&](bool heldout_only, double glider::diagnose::SpeedOfYo::*rms) {
    double sum = 0.0;
    std::size_t n = 0;
    for (auto y = u.by_yo.begin(); y != u.by_yo.end(); ++y) {
      if (y == worst || (heldout_only && !y->heldout)) continue;
      sum += (*y).*rms * (*y).*rms * static_cast<double>(y->samples);
      n += y->samples;
    }
    return n ? std::sqrt(sum / static_cast<double>(n)) : static_cast<double>(NAN);
  };
  using Yo = glider::diagnose::SpeedOfYo;
  std::printf(
      "  speed, worst yo: yo %d (%s, %zu samples) measured %.3f m/s, nominal %.3f, extended %.3f; without it: "
      "RMS nominal %.4f, extended %.4f m/s; held-out yos: nominal %.4f, extended %.4f m/s\n",
      worst->yo, worst->heldout ? "held out" : "fitted", worst->samples, worst->measured_mean_m_s,
      worst->nominal_mean_m_s, worst->extended_mean_m_s, without_worst(false, &Yo::nominal_rms_m_s),
      without_worst(false, &Yo::extended_rms_m_s), without_worst(true, &Yo::nominal_rms_m_s),
      without_worst(true, &Yo::extended_rms_m_s));
}

// The yos whose measured speed does not belong to their depth rate and
// pitch (speed_reference.hpp), and the score without them.
void print_reference_check(const glider::diagnose::SpeedScore& u) {
  std::string inconsistent;
  for (const auto& y : u.by_yo) {
    if (y.reference_consistent) continue;
    char text[160];
    std::snprintf(text, sizeof text, "%syo %d (%s: %+.1f mm/s)", inconsistent.empty() ? "" : ", ", y.yo,
                  y.heldout ? "held out" : "fitted", 1e3 * y.implied_water_w_m_s);
    inconsistent += text;
  }
  if (inconsistent.empty()) {
    std::printf("  speed reference check: every yo's measured speed fits its depth rate and pitch\n");
    return;
  }
  std::printf(
      "  speed reference check: the measured speed of %s implies a vertical water velocity at the model's glide "
      "path more than %.0f mm/s from the yos' median (%+.1f mm/s): not this flight's speed; without: RMS nominal "
      "%.4f, extended %.4f m/s; held-out yos: nominal %.4f, extended %.4f m/s\n",
      inconsistent.c_str(), 1e3 * info(Effect::kVerticalWaterVelocity).plausible_max,
      1e3 * u.implied_water_w_median_m_s, u.consistent_nominal_rms_m_s, u.consistent_extended_rms_m_s,
      u.heldout_consistent_nominal_rms_m_s, u.heldout_consistent_extended_rms_m_s);
}

void print_text(const Diagnosis& d, const std::string& log, const std::string& vehicle_source, double wall_s) {
  std::printf("Diagnosis of %s\n  vehicle: %s (%s)\n", log.c_str(), d.vehicle.c_str(), vehicle_source.c_str());
  const bool dynamic = d.model == glider::diagnose::FlightModelKind::kDynamic;
  if (d.retrimmed_to_kg_m3) {
    std::printf(
        "  trim density: the vehicle's %.1f kg/m^3 is far from this log's water: taken as ballasted for the "
        "log's median measured density, %.2f kg/m^3\n",
        *d.retrimmed_from_kg_m3, *d.retrimmed_to_kg_m3);
  }
  std::printf("  flight model: %s\n",
              dynamic ? "dynamic (the project's dynamics driven by the measured pitch, turns included)"
                      : "steady (steady glides at the measured pitch)");
  std::printf("  samples: %zu %s (%zu to fit, %zu held out: alternate yos)\n", d.samples_used,
              dynamic ? "scored" : "in steady glides", d.train_samples, d.heldout_samples);
  std::printf("  baseline (nominal model): depth rate RMS %.4f m/s (dives %.4f, climbs %.4f",
              d.baseline.all.depth_rate_m_s, d.baseline.dives.depth_rate_m_s, d.baseline.climbs.depth_rate_m_s);
  if (dynamic && d.baseline.inflections.samples > 0) std::printf(", turns %.4f", d.baseline.inflections.depth_rate_m_s);
  std::printf(")");
  if (d.baseline.rms_pitch_deg) std::printf(", pitch RMS %.2f deg", *d.baseline.rms_pitch_deg);
  if (d.baseline.rms_battpos_in) std::printf(", battery RMS %.3f in", *d.baseline.rms_battpos_in);
  std::printf("\n  by depth:");
  for (const auto& bin : d.baseline.by_depth)
    std::printf(" %.0f-%.0f m %.4f;", bin.from_m, bin.to_m, bin.rms.depth_rate_m_s);
  std::printf("\n  findings (strongest first):\n");
  if (d.findings.empty()) std::printf("    none: the nominal model explains the data within noise\n");
  for (const auto& f : d.findings) {
    std::printf("    %-24s %+.4g %s  (95%% CI %.4g .. %.4g)  held-out RMS %.4f m/s, gain %.0f %%\n", info(f.effect).id,
                f.value, info(f.effect).unit, f.ci95_low, f.ci95_high, f.heldout_rms_m_s, 100.0 * f.gain);
    if (f.effect == glider::diagnose::Effect::kThermalExpansion) {
      std::printf("      (about the log's median temperature, %.2f degC: the buoyancy there is the offset's)\n",
                  d.thermal_reference_c);
    }
  }
  for (const auto& a : d.ambiguities) {
    if (!a.ambiguous) {
      std::printf(
          "    told apart: %s, not %s (%+.4g %s in its place: held-out %.4f vs %.4f m/s; signatures correlate %.2f)\n",
          info(a.chosen).id, info(a.alternative).id, a.alternative_value, info(a.alternative).unit,
          a.alternative_heldout_rms_m_s, a.chosen_heldout_rms_m_s, a.correlation);
      continue;
    }
    std::printf(
        "    ambiguous: %s or %s %+.4g %s (95%% CI %.4g .. %.4g): fitted in its place it explains the held-out yos "
        "as well (%.4f vs %.4f m/s; signatures correlate %.2f): this log cannot tell them apart%s; what would: %s\n",
        info(a.chosen).id, info(a.alternative).id, a.alternative_value, info(a.alternative).unit,
        a.alternative_ci95_low, a.alternative_ci95_high, a.alternative_heldout_rms_m_s, a.chosen_heldout_rms_m_s,
        a.correlation,
        a.ruled_out_by_prior ? " (only the plausibility prior on its size rules the alternative out)" : "",
        a.separate.c_str());
  }
  for (const auto& b : d.beside) {
    if (!b.ambiguous) continue;
    if (b.lags_traded && b.partner_value == 0.0) {  // the pump lag read alone
      std::printf(
          "    ambiguous: %s as read (with %s beside it), or %+.4g %s (95%% CI %.4g .. %.4g) alone: the held-out yos "
          "tell them apart by less than the selection's margins (%.4f vs %.4f m/s); the interval above holds both "
          "readings; what would tell them apart: %s\n",
          info(b.finding).id, info(b.partner).id, b.finding_value, info(b.finding).unit, b.finding_ci95_low,
          b.finding_ci95_high, b.heldout_rms_m_s, b.chosen_heldout_rms_m_s, b.separate.c_str());
      continue;
    }
    // A reading beside that the held-out yos prefer but this log cannot
    // size, or one of the two lags traded (hold_traded_lag).
    const char* why = b.lags_traded ? "tell them apart by less than the selection's margins" : "prefer it";
    std::printf(
        "    ambiguous: %s as read, or %+.4g %s (95%% CI %.4g .. %.4g) with %s %+.4g %s (95%% CI %.4g .. %.4g) beside "
        "it: the held-out yos %s (%.4f vs %.4f m/s)%s; the interval above holds both readings; what would tell them "
        "apart: %s\n",
        info(b.finding).id, b.finding_value, info(b.finding).unit, b.finding_ci95_low, b.finding_ci95_high,
        info(b.partner).id, b.partner_value, info(b.partner).unit, b.partner_ci95_low, b.partner_ci95_high, why,
        b.heldout_rms_m_s, b.chosen_heldout_rms_m_s, b.lags_traded ? "" : " but this log cannot size it",
        b.separate.c_str());
  }
  for (const auto& u : d.unnamed) {
    if (u.ruled_out_by_prior) {
      std::printf(
          "    not named: %s %+.4g %s beside the findings: outside the plausible range, only the prior rules it "
          "out; what would size it: %s\n",
          info(u.effect).id, u.value, info(u.effect).unit, u.separate.c_str());
      continue;
    }
    std::printf("    not named: %s %+.4g %s (95%% CI %.4g .. %.4g) beside the findings: %s; what would size it: %s\n",
                info(u.effect).id, u.value, info(u.effect).unit, u.ci95_low, u.ci95_high,
                u.seen ? "seen by its interval, not confirmed by the held-out yos"
                       : "this log cannot rule out a term within the interval",
                u.separate.c_str());
  }
  std::printf(
      "  cause: %s\n  extended model: depth rate RMS %.4f m/s, held-out %.4f m/s (baseline held-out %.4f): gain %.0f "
      "%%\n",
      d.cause.c_str(), d.extended_all.depth_rate_m_s, d.extended_heldout_rms_m_s, d.baseline.heldout_rms_m_s,
      100.0 * d.gain);
  if (d.speed_through_water) {
    const auto& u = *d.speed_through_water;
    std::printf(
        "  speed through water vs measured (%zu samples, mean %.3f m/s; never fitted): RMS nominal %.4f, "
        "extended %.4f m/s; held-out yos (%zu): nominal %.4f, extended %.4f m/s\n",
        u.samples, u.measured_mean_m_s, u.nominal_rms_m_s, u.extended_rms_m_s, u.heldout_samples,
        u.heldout_nominal_rms_m_s, u.heldout_extended_rms_m_s);
    print_worst_yo(u);
    print_reference_check(u);
  }
  std::printf("  wall time: %.2f s (reading the log excluded)\n", wall_s);
}

// Plots a person would look at: measured and modelled depth rate over time
// and against depth, and the residuals before and after.
void write_plots(const std::string& dir, const glider::model::VehicleParams& vehicle,
                 const glider::diagnose::Observations& obs, const Diagnosis& d, const std::string& log_path,
                 const glider::diagnose::DiagnoseOptions& options) {
  const glider::diagnose::Predictions p = glider::diagnose::predict_all(vehicle, obs, d, options);
  const std::size_t n = p.time_s.size();
  std::vector<double> minutes(n), before(n), after(n);
  for (std::size_t i = 0; i < n; ++i) {
    minutes[i] = (p.time_s[i] - p.time_s[0]) / 60.0;
    before[i] = p.nominal_m_s[i] - p.measured_m_s[i];
    after[i] = p.extended_m_s[i] - p.measured_m_s[i];
  }
  glider::report::Report report(dir);
  report.text() << "# Diagnosis of " << std::filesystem::path(log_path).filename().string() << "\n\nCause: **"
                << d.cause << "**, held-out gain " << glider::report::fixed(100.0 * d.gain, 0)
                << " %. Numbers: diagnosis.json; extended vehicle: extended_vehicle.toml.\n";
  report.data("samples.dat",
              {"minutes", "depth_m", "measured", "nominal", "extended", "residual_before", "residual_after"},
              {minutes, p.depth_m, p.measured_m_s, p.nominal_m_s, p.extended_m_s, before, after});
  report.plot("depth_rate_time", "Depth rate over time: measured, nominal model, extended model",
              "set xlabel 'minutes'\nset ylabel 'depth rate (m/s, + down)'\n"
              "plot 'samples.dat' u 1:3 w p pt 7 ps 0.3 t 'measured', '' u 1:4 w p pt 7 ps 0.3 t 'nominal', "
              "'' u 1:5 w p pt 7 ps 0.3 t 'extended'");
  report.plot("depth_rate_depth", "Depth rate against depth: measured, nominal, extended",
              "set xlabel 'depth rate (m/s, + down)'\nset ylabel 'depth (m)'\nset yrange [*:*] reverse\n"
              "plot 'samples.dat' u 3:2 w p pt 7 ps 0.3 t 'measured', '' u 4:2 w p pt 7 ps 0.3 t 'nominal', "
              "'' u 5:2 w p pt 7 ps 0.3 t 'extended'");
  report.plot(
      "residuals", "Depth-rate residual (model - measured) against depth, before and after",
      "set xlabel 'residual (m/s)'\nset ylabel 'depth (m)'\nset yrange [*:*] reverse\n"
      "plot 'samples.dat' u 6:2 w p pt 7 ps 0.3 t 'nominal model', '' u 7:2 w p pt 7 ps 0.3 t 'extended model'");
  if (!p.pitch_time_s.empty()) {
    std::vector<double> pitch_minutes, measured, nominal, extended;
    for (std::size_t i = 0; i < p.pitch_time_s.size(); ++i) {
      pitch_minutes.push_back((p.pitch_time_s[i] - p.time_s[0]) / 60.0);
      measured.push_back(glider::rad_to_deg(p.pitch_measured_rad[i]));
      nominal.push_back(glider::rad_to_deg(p.pitch_nominal_rad[i]));
      extended.push_back(glider::rad_to_deg(p.pitch_extended_rad[i]));
    }
    report.data("pitch.dat", {"minutes", "depth_m", "measured_deg", "nominal_deg", "extended_deg"},
                {pitch_minutes, p.pitch_depth_m, measured, nominal, extended});
    report.plot("pitch_time",
                "Pitch on the steady glides: measured, and the equilibrium pitch of the nominal and extended "
                "vehicles for the logged ballast and battery",
                "set xlabel 'minutes'\nset ylabel 'pitch (deg, + nose up)'\n"
                "plot 'pitch.dat' u 1:3 w p pt 7 ps 0.3 t 'measured', '' u 1:4 w p pt 7 ps 0.3 t 'nominal', "
                "'' u 1:5 w p pt 7 ps 0.3 t 'extended'");
    report.plot("pitch_depth", "Pitch against depth: measured, nominal, extended",
                "set xlabel 'pitch (deg)'\nset ylabel 'depth (m)'\nset yrange [*:*] reverse\n"
                "plot 'pitch.dat' u 3:2 w p pt 7 ps 0.3 t 'measured', '' u 4:2 w p pt 7 ps 0.3 t 'nominal', "
                "'' u 5:2 w p pt 7 ps 0.3 t 'extended'");
  }
  if (!p.speed_measured_m_s.empty()) {
    report.data("speed.dat", {"minutes", "depth_m", "measured", "nominal", "extended"},
                {minutes, p.depth_m, p.speed_measured_m_s, p.speed_nominal_m_s, p.speed_extended_m_s});
    report.plot("speed_time", "Speed through water: measured (never fitted), nominal model, extended model",
                "set xlabel 'minutes'\nset ylabel 'speed through water (m/s)'\n"
                "plot 'speed.dat' u 1:3 w p pt 7 ps 0.3 t 'measured', '' u 1:4 w p pt 7 ps 0.3 t 'nominal', "
                "'' u 1:5 w p pt 7 ps 0.3 t 'extended'");
  }
  if (!report.finish()) throw std::runtime_error("the plots could not be rendered (gnuplot)");
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool(
      "glider-diagnose",
      "Show what the simulation gets wrong in a flight log, name the cause, fit it, measure the gain");
  CLI::App& app = tool.app();
  std::string log_path, vehicle_path, report_dir;
  std::string default_vehicle;
  bool json = false;
  std::vector<std::string> renames;
  std::string flight_model = "dynamic";
  std::string plane = "both";
  std::string intervals = "glides";
  std::vector<std::string> fit_only;
  std::vector<double> window;
  double rate_window_s = glider::diagnose::TrackOptions{}.rate_half_window_s;
  double score_block_s = glider::diagnose::DiagnoseOptions{}.score_block_s;
  std::string autopilot_integrator = "per-glide";
  std::string yaw_lag_pole = "profiled";
  std::string autopilot_clock = "both";
  double yaw_fast_pole_max_s = -1.0;
  double drag_reynolds_exponent = glider::diagnose::kDragReynoldsExponentPrior;
  double pitch_window_s = glider::diagnose::TrackOptions{}.pitch_half_window_s;
  glider::diagnose::PitchCalibration pitch_calibration;
  glider::slocum::LogSource log_source;
  app.add_option("LOG", log_source.inputs,
                 "flight log: a CSV (docs/flight-log.md), or a glider's binary files (.dbd/.ebd..., LZ4 .dcd/.ecd...: "
                 "files, a directory or globs; docs/slocum-binary.md)")
      ->required();
  app.add_option("--cache", log_source.cache_dirs,
                 "sensor-list cache directory for binary files (default: their folder and its cac/)");
  app.add_option("--vehicle", vehicle_path,
                 "nominal vehicle file (else the log's vehicle.* metadata, else --default-vehicle, else the vehicle "
                 "boards/gliders.toml gives for the glider the log names)")
      ->check(CLI::ExistingFile);
  app.add_option("--default-vehicle", default_vehicle, "vehicle used when neither --vehicle nor metadata give one")
      ->check(CLI::ExistingFile);
  app.add_option("--report", report_dir, "write the summary and the extended vehicle file here");
  tool.add_json_flag(json);
  app.add_option("--rename", renames, "read column FROM as TO (FROM=TO), for logs not in the contract's names");
  app.add_option("--model", flight_model,
                 "flight model fitted: dynamic (the project's dynamics driven by the measured pitch, turns "
                 "included) or steady (steady glides at the measured pitch; faster, blind to turns)")
      ->check(CLI::IsMember({"dynamic", "steady"}));
  app.add_option("--plane", plane,
                 "which plane to diagnose: vertical (depth rate), heading (servo, yaw, autopilot) or both")
      ->check(CLI::IsMember({"vertical", "heading", "both"}))
      ->capture_default_str();
  app.add_option("--intervals", intervals,
                 "how the 95 % intervals (both planes) count the serially correlated samples: glides or yos "
                 "(cluster-robust, each glide or yo a cluster) or lag1 (the noise over an AR(1)'s effective sample "
                 "count, the rule before issue 26's fitting core; fitting_core/intervals.hpp)")
      ->check(CLI::IsMember({"lag1", "glides", "yos"}))
      ->capture_default_str();
  app.add_option("--autopilot-integrator", autopilot_integrator,
                 "the heading autopilot's integrator at each glide's start: per-glide (a state per glide, profiled "
                 "out of the autopilot link's residuals) or replayed (from the log's start, the rule before; "
                 "docs/science.md)")
      ->check(CLI::IsMember({"per-glide", "replayed"}))
      ->capture_default_str();
  app.add_option("--autopilot-clock", autopilot_clock,
                 "the clock the heading autopilot's law integrates over: measured (each cycle's interval, the rule "
                 "before), nominal (the log's median cycle), both (both fitted: what both name, intervals over "
                 "both) or held-out (the held-out rows choose where they tell the clocks apart, else both; "
                 "docs/science.md \"The autopilot's clock\")")
      ->check(CLI::IsMember({"measured", "nominal", "both", "held-out"}))
      ->capture_default_str();
  app.add_option("--yaw-lag-pole", yaw_lag_pole,
                 "the yaw's lag measured on the innovations beside the fast pole: profiled (read with the pole at "
                 "0 and at its prior's centre and upper end, the likeliest's value, the interval spanning the "
                 "poles the log cannot tell apart) or none (no pole beside it, the rule before; docs/science.md "
                 "\"The yaw's lag beside the fast pole, profiled\")")
      ->check(CLI::IsMember({"profiled", "none"}))
      ->capture_default_str();
  // -1, not a range's end: the default follows the vehicle file, so a sentinel in the declared range stands for it.
  tool.add_number("--yaw-fast-pole", yaw_fast_pole_max_s, {-1.0, 30.0, "s"},
                  "upper end (s) of the heading model's fast yaw pole's prior (uniform from 0; the models carry its "
                  "centre, the yaw delay's interval spans it): -1 (the default) = half the vehicle file's yaw time "
                  "constant, 0 = no fast pole (the rule before; docs/science.md \"The yaw's fast pole\")");
  app.add_option("--fit", fit_only,
                 "fit exactly these effects (ids), no selection: e.g. --fit drag_change,buoyancy_offset")
      ->delimiter(',');
  tool.add_numbers("--window-m", window, {0.0, 11000.0, "m"},
                   "score and fit only samples between these depths (m): --window-m 10,35")
      ->delimiter(',')
      ->expected(2);
  tool.add_number("--rate-window", rate_window_s, {0.0, 60.0, "s"},
                  "the measured depth rate is the slope of the depth over +-this many seconds (0: centred difference)");
  tool.add_number("--score-block", score_block_s, {0.0, 600.0, "s"},
                  "the selection compares held-out residuals averaged over blocks of a glide this long (0: sample "
                  "by sample; fitting_core/block_score.hpp)");
  const CLI::Option* drag_reynolds_option = tool.add_number(
      "--drag-reynolds-exponent", drag_reynolds_exponent, {0.0, 0.5, ""},
      "the skin friction's Reynolds exponent n of the fitted model, C_D0 (V/V_ref)^-n, V_ref the vehicle "
      "file's hydrodynamics.cd0_reference_speed_m_s (default: the file's exponent if it states one, else "
      "the prior 0.1; 0: off, the model before it; docs/science.md)");
  tool.add_number("--pitch-window", pitch_window_s, {0.0, 60.0, "s"},
                  "the measured pitch (the dynamic model's input) is smoothed over +-this many seconds (0: as logged)");
  using Calibration = glider::diagnose::PitchCalibration;
  tool.add_number("--pitch-scale", pitch_calibration.scale, {Calibration::kMinScale, Calibration::kMaxScale, ""},
                  "pitch sensor calibration, off by default: the pitch diagnosed is SCALE m_pitch + OFFSET "
                  "(comet: 0.86, gliderflight's tilt correction; docs/science.md)");
  tool.add_number("--pitch-offset", pitch_calibration.offset_rad,
                  {-Calibration::kMaxAbsOffsetRad, Calibration::kMaxAbsOffsetRad, "rad"},
                  "pitch sensor calibration's offset (comet: -0.004 rad), with --pitch-scale");
  return tool.run(argc, argv, [&]() -> int {
    log_path = log_source.inputs.front();
    glider::diagnose::DiagnoseOptions options;
    options.score_block_s = score_block_s;
    options.model = flight_model == "steady" ? glider::diagnose::FlightModelKind::kSteady
                                             : glider::diagnose::FlightModelKind::kDynamic;
    options.intervals = intervals == "yos"      ? glider::diagnose::DiagnoseOptions::Intervals::kYos
                        : intervals == "glides" ? glider::diagnose::DiagnoseOptions::Intervals::kGlides
                                                : glider::diagnose::DiagnoseOptions::Intervals::kLag1;
    glider::diagnose::HeadingDiagnoseOptions heading_options;
    heading_options.intervals = options.intervals;
    heading_options.autopilot_integrator_per_glide = autopilot_integrator == "per-glide";
    heading_options.yaw_lag_fast_pole = yaw_lag_pole == "profiled";
    heading_options.track.yaw_fast_pole_max_s = yaw_fast_pole_max_s;
    using glider::diagnose::AutopilotClockRule;
    heading_options.autopilot_clock = autopilot_clock == "measured"   ? AutopilotClockRule::kMeasured
                                      : autopilot_clock == "nominal"  ? AutopilotClockRule::kNominal
                                      : autopilot_clock == "held-out" ? AutopilotClockRule::kHeldOut
                                                                      : AutopilotClockRule::kBoth;
    std::vector<std::string> depth_rate_ids;
    for (const std::string& id : fit_only) {
      bool heading_id = false;
      for (std::size_t i = 0; i < glider::diagnose::kHeadingEffectCount; ++i) {
        const auto e = static_cast<glider::diagnose::HeadingEffect>(i);
        if (id == glider::diagnose::info(e).id) {
          heading_options.fit_only.push_back(e);
          heading_id = true;
        }
      }
      if (!heading_id) depth_rate_ids.push_back(id);
    }
    try {
      options.fit_only = glider::diagnose::depth_rate_effects(depth_rate_ids);
    } catch (const std::invalid_argument& error) {
      return tool.fail(glider::cli::kUsage, std::string(error.what()) + " (nor a heading effect id)");
    }
    const bool vertical_plane = plane != "heading";
    const bool heading_plane = plane != "vertical";
    if (window.size() == 2) {
      options.window_min_m = window[0];
      options.window_max_m = window[1];
    }
    glider::diagnose::ObservationOptions observation_options;
    observation_options.track.rate_half_window_s = rate_window_s;
    observation_options.track.pitch_half_window_s = pitch_window_s;

    try {
      glider::flightlog::ReadOptions read_options;
      read_options.rename = glider::diagnose::column_renames(renames);
      std::vector<glider::slocum::Warning> warnings;
      // The pitch calibration, when asked for, is applied to the log itself: both planes see the same pitch.
      const glider::flightlog::FlightLog log = glider::diagnose::calibrate_pitch(
          glider::slocum::load_flight_log(log_source, read_options, &warnings), pitch_calibration);
      for (const auto& w : warnings) std::fprintf(stderr, "glider-diagnose: warning: %s\n", w.text().c_str());
      // A log that did not end cleanly is still diagnosed, but the user is told.
      if (log.end().unfinished() || log.end().state == glider::flightlog::LogEnd::State::kAborted) {
        std::fprintf(stderr, "glider-diagnose: %s: %s\n", log_path.c_str(), log.end().describe(log.rows()).c_str());
      }
      const glider::diagnose::NominalVehicle nominal =
          glider::diagnose::nominal_vehicle({vehicle_path, default_vehicle, glider::cli::boards_dir()}, log, log_path);
      const glider::model::VehicleParams& vehicle = nominal.params;
      // Unasked, diagnose() chooses (drag_reynolds_exponent_for: the file's, else the prior).
      if (drag_reynolds_option->count() > 0) options.drag_reynolds_exponent = drag_reynolds_exponent;
      const std::string& vehicle_source = nominal.source;
      const auto start = std::chrono::steady_clock::now();
      // Progress on stderr once a run has taken more than 2 s, at most a line a second.
      std::size_t fits = 0;
      double last_line_s = 0.0;
      const std::size_t rows = log.rows();
      options.progress = [&](const std::string& fitting) {
        ++fits;
        const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (elapsed_s < 2.0 || elapsed_s - last_line_s < 1.0) return;
        last_line_s = elapsed_s;
        std::fprintf(stderr, "glider-diagnose: %.0f s, %zu rows: model fit %zu (%s)\n", elapsed_s, rows, fits,
                     fitting.c_str());
      };
      std::optional<glider::diagnose::Observations> obs;
      std::optional<Diagnosis> vertical;
      if (vertical_plane) {
        obs = glider::diagnose::prepare_observations(log, observation_options);
        vertical = glider::diagnose::diagnose(vehicle, *obs, options);
      }
      // The heading plane's glide speed and the roll's yaw from the vertical plane's findings (heading_vehicle).
      const glider::model::VehicleParams flown =
          vertical ? glider::diagnose::heading_vehicle(vehicle, *vertical) : vehicle;
      // The heading plane second, on the flown vehicle: a log it cannot read is said so, the vertical result stands.
      std::optional<glider::diagnose::HeadingDiagnosis> heading;
      ordered_json heading_object;
      if (heading_plane) {
        // A decimated file (.sbd, ...) stores the commands and the fin on change: read as health reads it.
        const bool decimated = glider::slocum::is_binary_log(log_source.inputs) &&
                               glider::diagnose::any_decimated(glider::slocum::deployment_files(log_source.inputs));
        heading_options.track.fin_stored_on_change = decimated;
        glider::diagnose::HeadingPlane h = glider::diagnose::heading_plane(
            flown,
            decimated ? glider::diagnose::hold_stored_columns(log, glider::diagnose::kStoredHoldMaxAgeS, false) : log,
            heading_options);
        if (!h.diagnosis) {
          const std::string reason = h.json["reason"].get<std::string>();
          if (!vertical_plane) throw std::runtime_error(reason);
          std::fprintf(stderr, "glider-diagnose: heading plane: %s\n", reason.c_str());
        }
        heading = std::move(h.diagnosis);
        heading_object = std::move(h.json);
      }
      const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      auto document = [&] {
        ordered_json j = vertical ? to_json(*vertical, vehicle_source, wall_s)
                                  : ordered_json{{"vehicle", vehicle.name}, {"vehicle_source", vehicle_source}};
        if (pitch_calibration.active()) {
          j["pitch_calibration"] = {{"scale", pitch_calibration.scale},
                                    {"offset_rad", pitch_calibration.offset_rad},
                                    {"pitch", pitch_calibration.describe()}};
        }
        if (heading_plane) j["heading"] = heading_object;
        return j;
      };
      if (json) {
        std::printf("%s\n", document().dump().c_str());
      } else {
        if (pitch_calibration.active()) std::printf("pitch calibrated: %s\n", pitch_calibration.describe().c_str());
        if (vertical) print_text(*vertical, log_path, vehicle_source, wall_s);
        if (heading) std::printf("%s", glider::diagnose::heading_text(*heading).c_str());
      }
      if (!report_dir.empty()) {
        std::filesystem::create_directories(report_dir);
        if (vertical) write_plots(report_dir, vehicle, *obs, *vertical, log_path, options);
        glider::report::write_file(std::filesystem::path(report_dir) / "diagnosis.json", document().dump(2) + '\n');
        glider::model::VehicleParams extended =
            vertical ? glider::diagnose::apply(glider::diagnose::diagnosed_nominal(vehicle, *vertical),
                                               vertical->extended, vertical->thermal_reference_c)
                     : vehicle;
        if (heading) extended = glider::diagnose::apply(extended, *heading);
        extended.name = vehicle.name + "_extended";
        extended.description =
            "extended by glider-diagnose from " + std::filesystem::path(log_path).filename().string();
        glider::report::write_file(
            std::filesystem::path(report_dir) / "extended_vehicle.toml",
            "# Written by glider-diagnose. Water effects (vertical velocity, density) belong to the\n"
            "# environment, not the vehicle: see diagnosis.json.\n" +
                glider::model::vehicle_file_text(extended));
      }
    } catch (const std::exception& error) {
      return tool.fail(glider::cli::kError, error.what());
    }
    return static_cast<int>(glider::cli::kOk);
  });
}
