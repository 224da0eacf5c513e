// SPDX-License-Identifier: Apache-2.0
// glider-dvl-protocol: glider-diagnose and gliderflight's flight model side
// by side against a measured speed through water (a DVL's), under one
// protocol: both fitted on the same training yos (the even ones: the
// diagnosis's own split), both scored on the same held-out yos (the odd
// ones), at the same samples, with every yo and without the yos whose
// reference fails the diagnosis's reference check (speed_reference.hpp).
// The speed is never fitted by either. docs/diagnose/README.md, "One
// protocol". gliderflight's model is this project's implementation of its
// published equations (gliderflight_model.hpp), checked against the
// package's own example fit first (printed).
//
//   glider-dvl-protocol tests/data/real/gliderflight-adcp.csv --vehicle boards/vehicles/slocum_shallow.toml
//       --rename time=m_present_time ... (./glider dvl-protocol does this)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "glider/cli/tool.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/diagnose/pitch_calibration.hpp"
#include "glider/diagnose/tool_inputs.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/science/gliderflight_model.hpp"
#include "glider/science/speed_error_breakdown.hpp"
#include "glider/slocum/log_loader.hpp"

namespace {

using glider::science::GliderflightInput;
using glider::science::GliderflightKind;
using glider::science::GliderflightParameters;

// The log's records that gliderflight can use (every input present), with
// their row times.
GliderflightInput gliderflight_input(const glider::flightlog::FlightLog& log) {
  const auto& t = log.column("m_present_time");
  const auto& p = log.column("sci_water_pressure");
  const auto& pitch = log.column("m_pitch");
  const auto& vb = log.column("m_ballast_pumped");
  const auto* rho = log.find("sci_water_density");
  if (rho == nullptr) throw std::runtime_error("the log has no sci_water_density: gliderflight's model needs it");
  GliderflightInput in;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i] + p[i] + pitch[i] + vb[i] + (*rho)[i])) continue;
    if (!in.time_s.empty() && !(t[i] > in.time_s.back())) continue;
    in.time_s.push_back(t[i]);
    in.pressure_bar.push_back(p[i]);
    in.pitch_rad.push_back(pitch[i]);
    in.buoyancy_change_cc.push_back(vb[i]);
    in.density_kg_m3.push_back((*rho)[i]);
  }
  return in;
}

// The vertical water velocity glider-diagnose fitted (its depth profile, else its constant), m/s + down.
double fitted_water_at(const glider::diagnose::Diagnosis& d, double depth_m) {
  if (d.extended_profile) return d.extended_profile->at(depth_m);
  return d.extended[static_cast<std::size_t>(glider::diagnose::Effect::kVerticalWaterVelocity)];
}

bool water_fitted(const glider::diagnose::Diagnosis& d) {
  return d.extended_profile.has_value() ||
         d.extended[static_cast<std::size_t>(glider::diagnose::Effect::kVerticalWaterVelocity)] != 0.0;
}

std::string water_text(const glider::diagnose::Diagnosis& d) {
  std::string text;
  char item[64];
  if (d.extended_profile) {
    const auto& p = *d.extended_profile;
    for (std::size_t b = 0; b < p.w_m_s.size(); ++b) {
      std::snprintf(item, sizeof item, "%s%.0f-%.0f m %+.1f", b == 0 ? "" : ", ",
                    p.first_m + p.bin_m * static_cast<double>(b), p.first_m + p.bin_m * static_cast<double>(b + 1),
                    1e3 * p.w_m_s[b]);
      text += item;
    }
    return text + " mm/s, + down";
  }
  std::snprintf(item, sizeof item, "%+.1f mm/s, + down",
                1e3 * d.extended[static_cast<std::size_t>(glider::diagnose::Effect::kVerticalWaterVelocity)]);
  return item;
}

// gliderflight's records with glider-diagnose's fitted water velocity at each record's depth (from its pressure).
GliderflightInput with_water(GliderflightInput in, const glider::diagnose::Diagnosis& d) {
  if (!water_fitted(d)) {
    throw std::runtime_error(
        "--shared-water: glider-diagnose fitted no vertical water velocity (add vertical_water_velocity to --fit)");
  }
  constexpr double kGravity = 9.80665;
  in.water_w_down_m_s.resize(in.time_s.size());
  for (std::size_t i = 0; i < in.time_s.size(); ++i) {
    const double depth_m = in.pressure_bar[i] * 1e5 / (in.density_kg_m3[i] * kGravity);
    in.water_w_down_m_s[i] = fitted_water_at(d, depth_m);
  }
  return in;
}

// gliderflight's example mask: 10-35 dbar.
bool in_example_window(double pressure_bar) { return pressure_bar * 10.0 >= 10.0 && pressure_bar * 10.0 <= 35.0; }

double rms(const std::vector<double>& model, const std::vector<double>& measured, const std::vector<bool>& use) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (!use[i] || !std::isfinite(model[i] - measured[i])) continue;
    sum += (model[i] - measured[i]) * (model[i] - measured[i]);
    ++n;
  }
  return n > 0 ? std::sqrt(sum / static_cast<double>(n)) : std::nan("");
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-dvl-protocol",
                         "glider-diagnose and gliderflight's model against a DVL's speed through water: both fitted "
                         "on the even yos, both scored on the odd yos, with and without the yos the reference check "
                         "excludes");
  CLI::App& app = tool.app();
  std::string log_path, vehicle_path;
  std::vector<std::string> renames, fit_only;
  app.add_option("LOG", log_path, "flight log with sci_speed_through_water and sci_water_density")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--vehicle", vehicle_path, "nominal vehicle file for glider-diagnose")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--rename", renames, "read column FROM as TO (FROM=TO)");
  std::string samples_path;
  app.add_option("--samples", samples_path,
                 "write every scored sample here: time, depth, yo, measured, glider-diagnose, gliderflight dynamic, "
                 "steady (m/s), pitch (rad), depth rate measured, glider-diagnose's, gliderflight dynamic's (m/s, + "
                 "down)");
  app.add_option("--fit", fit_only, "glider-diagnose fits exactly these effects (default: its free selection)")
      ->delimiter(',');
  // The pitch calibration (glider-diagnose's): applied to the log, so both models fly the same pitch.
  using Calibration = glider::diagnose::PitchCalibration;
  Calibration pitch_calibration;
  tool.add_number("--pitch-scale", pitch_calibration.scale, {Calibration::kMinScale, Calibration::kMaxScale, ""},
                  "pitch sensor calibration for both models: SCALE m_pitch + OFFSET (default: as stored)");
  tool.add_number("--pitch-offset", pitch_calibration.offset_rad,
                  {-Calibration::kMaxAbsOffsetRad, Calibration::kMaxAbsOffsetRad, "rad"},
                  "pitch sensor calibration's offset, with --pitch-scale");
  double drag_reynolds_exponent = glider::diagnose::kDragReynoldsExponentPrior;
  const CLI::Option* drag_reynolds_option =
      tool.add_number("--drag-reynolds-exponent", drag_reynolds_exponent, {0.0, 0.5, ""},
                      "glider-diagnose's skin-friction Reynolds exponent (as glider-diagnose: the vehicle file's if it "
                      "states one, else the prior 0.1; 0: off)");
  bool gliderflight_epsilon = false;
  app.add_flag("--gliderflight-epsilon", gliderflight_epsilon,
               "the protocol's gliderflight fits also fit its hull compressibility epsilon (as gliderflight's "
               "calibrate can; for comparisons where glider-diagnose fits hull_compressibility)");
  bool shared_water = false;
  app.add_flag("--shared-water", shared_water,
               "both models carry the same vertical water velocity: the one glider-diagnose fits on the even yos "
               "(vertical_water_velocity in --fit or its selection: a depth profile) is given to gliderflight's "
               "calibration, whose depth rate is then its flight plus that water (the speeds scored do not depend "
               "on it, the fitted parameters do)");
  double score_block_s = glider::diagnose::DiagnoseOptions{}.score_block_s;
  tool.add_number("--score-block", score_block_s, {0.0, 600.0, "s"},
                  "glider-diagnose's selection score: held-out residuals averaged over blocks of a glide this long "
                  "(0: sample by sample; as glider-diagnose --score-block)");
  return tool.run(argc, argv, [&]() -> int {
    glider::flightlog::ReadOptions read_options;
    read_options.rename = glider::diagnose::column_renames(renames);
    const glider::flightlog::FlightLog log = glider::diagnose::calibrate_pitch(
        glider::slocum::load_flight_log({{log_path}, {}}, read_options, nullptr), pitch_calibration);
    const glider::model::VehicleParams vehicle = glider::model::load_vehicle_file(vehicle_path);
    const glider::diagnose::Observations obs = glider::diagnose::prepare_observations(log);
    glider::diagnose::DiagnoseOptions options;
    options.fit_only = glider::diagnose::depth_rate_effects(fit_only);
    if (drag_reynolds_option->count() > 0) options.drag_reynolds_exponent = drag_reynolds_exponent;
    options.score_block_s = score_block_s;
    const glider::diagnose::Diagnosis d = glider::diagnose::diagnose(vehicle, obs, options);
    if (!d.speed_through_water) throw std::runtime_error(log_path + ": no sci_speed_through_water to score");
    const glider::diagnose::Predictions pred = glider::diagnose::predict_all(vehicle, obs, d, options);

    // Yo of each steady-glide sample, by its time (the diagnosis's split: even yos fitted).
    std::map<double, int> yo_at;
    for (std::size_t i = 0; i < obs.size(); ++i) yo_at[obs.time_s[i]] = obs.yo[i];
    std::set<int> excluded;
    for (const auto& y : d.speed_through_water->by_yo) {
      if (!y.reference_consistent) excluded.insert(y.yo);
    }

    // gliderflight's records, and which of them the protocol fits on: the
    // steady-glide samples of the even yos (the same samples glider-diagnose
    // fits), inside gliderflight's own 10-35 dbar window.
    const GliderflightInput in = gliderflight_input(log);
    const std::size_t n = in.time_s.size();
    std::vector<bool> fit_even(n, false), fit_all_example(n, false);
    for (std::size_t i = 0; i < n; ++i) {
      fit_all_example[i] = in_example_window(in.pressure_bar[i]);
      const auto it = yo_at.find(in.time_s[i]);
      fit_even[i] = it != yo_at.end() && it->second % 2 == 0 && in_example_window(in.pressure_bar[i]);
    }

    // 1. gliderflight's example fit (all records, 10-35 dbar) reproduced.
    const auto* dvl_column = log.find("sci_speed_through_water");
    std::map<double, double> dvl_at;
    for (std::size_t i = 0; i < log.rows(); ++i) {
      if (std::isfinite((*dvl_column)[i])) dvl_at[log.column("m_present_time")[i]] = (*dvl_column)[i];
    }
    std::vector<double> dvl(n, std::nan(""));
    std::vector<bool> every(n, true);
    for (std::size_t i = 0; i < n; ++i) {
      const auto it = dvl_at.find(in.time_s[i]);
      if (it != dvl_at.end()) dvl[i] = it->second;
    }
    std::printf("%s: %zu records, %zu with a DVL speed; %zu steady-glide samples (diagnosis)\n", log_path.c_str(), n,
                dvl_at.size(), obs.size());
    std::printf("pitch calibration, both models: %s\n", pitch_calibration.describe().c_str());
    std::printf(
        "\ngliderflight's example fit reproduced (C_D0 and m_g on the depth rate of all records at 10-35 dbar;\n"
        "its published figures: depth-rate RMS 3.92 cm/s; DVL RMS on all samples 0.0284 m/s dynamic, 0.0480 "
        "steady):\n");
    GliderflightParameters fitted[2];
    for (const auto kind : {GliderflightKind::kDynamic, GliderflightKind::kSteady}) {
      double fit_rms = 0.0;
      const GliderflightParameters p = glider::science::gliderflight_calibrate(kind, {}, in, fit_all_example, &fit_rms);
      const auto r = glider::science::gliderflight_solve(kind, p, in);
      std::printf("  %-7s C_D0 %.4f  m_g %.3f kg  depth-rate RMS %.2f cm/s  DVL RMS all samples %.4f m/s\n",
                  kind == GliderflightKind::kDynamic ? "dynamic" : "steady", p.cd0, p.mass_kg, 100.0 * fit_rms,
                  rms(r.speed_m_s, dvl, every));
    }

    // 2. The protocol.
    const GliderflightInput in_protocol = shared_water ? with_water(in, d) : in;
    if (shared_water) {
      std::printf(
          "\nwater term, both models: glider-diagnose's vertical water velocity fitted on the even yos (%s), "
          "given to gliderflight's calibration\n",
          water_text(d).c_str());
    }
    std::vector<double> gf_speed[2], gf_dynamic_w;
    for (int k = 0; k < 2; ++k) {
      const auto kind = k == 0 ? GliderflightKind::kDynamic : GliderflightKind::kSteady;
      fitted[k] = glider::science::gliderflight_calibrate(kind, {}, in_protocol, fit_even, nullptr,
                                                          gliderflight_epsilon
                                                              ? glider::science::GliderflightFit::kCd0MassEpsilon
                                                              : glider::science::GliderflightFit::kCd0Mass);
      auto solved = glider::science::gliderflight_solve(kind, fitted[k], in);
      if (glider::science::gliderflight_diverged(solved, fit_even)) {
        // No score from a fit that left the model's domain (the breakdown's truth check skips such logs).
        std::printf(
            "\ngliderflight %s: its fit diverged (its model not finite at most of the fitted records): "
            "no score\n",
            k == 0 ? "dynamic" : "steady");
        std::fill(solved.speed_m_s.begin(), solved.speed_m_s.end(), std::nan(""));
        std::fill(solved.w_m_s.begin(), solved.w_m_s.end(), std::nan(""));
      }
      gf_speed[k] = solved.speed_m_s;
      if (k == 0) gf_dynamic_w = solved.w_m_s;
    }
    std::map<double, std::size_t> record_at;
    for (std::size_t i = 0; i < n; ++i) record_at[in.time_s[i]] = i;
    // The scored samples: the diagnosis's, with a DVL speed and a gliderflight record.
    std::vector<double> measured, ours, gf[2];
    std::vector<int> yo;
    std::vector<glider::science::ScoredSpeedSample> scored;
    for (std::size_t i = 0; i < pred.time_s.size(); ++i) {
      const auto r = record_at.find(pred.time_s[i]);
      const auto y = yo_at.find(pred.time_s[i]);
      if (r == record_at.end() || y == yo_at.end() || !std::isfinite(pred.speed_measured_m_s[i])) continue;
      measured.push_back(pred.speed_measured_m_s[i]);
      ours.push_back(pred.speed_extended_m_s[i]);
      gf[0].push_back(gf_speed[0][r->second]);
      gf[1].push_back(gf_speed[1][r->second]);
      yo.push_back(y->second);
      glider::science::ScoredSpeedSample s;
      s.time_s = pred.time_s[i];
      s.depth_m = pred.depth_m[i];
      s.yo = y->second;
      s.measured_m_s = measured.back();
      s.model_m_s = {ours.back(), gf[0].back()};
      s.pitch_rad = in.pitch_rad[r->second];
      s.depth_rate_measured_m_s = pred.measured_m_s[i];
      s.depth_rate_model_m_s = {pred.extended_m_s[i], -gf_dynamic_w[r->second]};
      scored.push_back(s);
    }
    if (!samples_path.empty()) {
      std::FILE* f = std::fopen(samples_path.c_str(), "w");
      if (f == nullptr) throw std::runtime_error("cannot write " + samples_path);
      std::fprintf(f,
                   "# time_s depth_m yo measured_m_s glider_diagnose_m_s gliderflight_dynamic_m_s "
                   "gliderflight_steady_m_s pitch_rad depth_rate_measured_m_s depth_rate_glider_diagnose_m_s "
                   "depth_rate_gliderflight_dynamic_m_s\n");
      std::size_t k = 0;
      for (std::size_t i = 0; i < pred.time_s.size(); ++i) {
        if (record_at.count(pred.time_s[i]) == 0 || yo_at.count(pred.time_s[i]) == 0 ||
            !std::isfinite(pred.speed_measured_m_s[i])) {
          continue;
        }
        const auto& s = scored[k];
        std::fprintf(f, "%.3f %.3f %d %.5f %.5f %.5f %.5f %.5f %.5f %.5f %.5f\n", s.time_s, s.depth_m, s.yo,
                     s.measured_m_s, s.model_m_s[0], s.model_m_s[1], gf[1][k], s.pitch_rad, s.depth_rate_measured_m_s,
                     s.depth_rate_model_m_s[0], s.depth_rate_model_m_s[1]);
        ++k;
      }
      if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + samples_path);
    }
    auto select = [&](bool heldout_only, bool without_excluded) {
      std::vector<bool> use(yo.size());
      for (std::size_t i = 0; i < yo.size(); ++i) {
        use[i] = (!heldout_only || yo[i] % 2 == 1) && (!without_excluded || excluded.count(yo[i]) == 0);
      }
      return use;
    };
    auto count = [](const std::vector<bool>& use) { return std::count(use.begin(), use.end(), true); };
    const auto held = select(true, false), held_kept = select(true, true), all = select(false, false),
               all_kept = select(false, true);
    std::string excluded_text;
    for (int y : excluded) {
      for (const auto& b : d.speed_through_water->by_yo) {
        if (b.yo != y) continue;
        char line[160];
        std::snprintf(line, sizeof line, "%syo %d (implied vertical water velocity %+.1f mm/s, log median %+.1f)",
                      excluded_text.empty() ? "" : ", ", y, 1e3 * b.implied_water_w_m_s,
                      1e3 * d.speed_through_water->implied_water_w_median_m_s);
        excluded_text += line;
      }
    }
    std::printf(
        "\nThe protocol: fitted on the even yos, scored on the odd yos (%ld DVL samples held out, %ld without "
        "the excluded yos).\nExcluded by the reference check: %s.\n\n",
        static_cast<long>(count(held)), static_cast<long>(count(held_kept)),
        excluded_text.empty() ? "none" : excluded_text.c_str());
    std::string findings;
    for (const auto& f : d.findings) {
      char item[96];
      std::snprintf(item, sizeof item, "%s%s %.4g", findings.empty() ? "" : ", ", glider::diagnose::info(f.effect).id,
                    f.value);
      findings += item;
    }
    std::printf(
        "| model (fitted on the even yos' depth rate) | held out, every yo (cm/s) | held out, without "
        "excluded (cm/s) | all yos, every yo | all yos, without excluded |\n|---|---|---|---|---|\n");
    auto row = [&](const std::string& name, const std::vector<double>& model) {
      std::printf("| %s | %.2f | %.2f | %.2f | %.2f |\n", name.c_str(), 100.0 * rms(model, measured, held),
                  100.0 * rms(model, measured, held_kept), 100.0 * rms(model, measured, all),
                  100.0 * rms(model, measured, all_kept));
    };
    row("glider-diagnose, " + std::string(glider::diagnose::to_string(d.model)) + " (" +
            (options.fit_only.empty() ? "free selection: " : "fitted: ") + findings + ")",
        ours);
    char name[160];
    auto epsilon_text = [&](const GliderflightParameters& p) {
      char text[48] = "";
      if (gliderflight_epsilon) std::snprintf(text, sizeof text, ", eps %.3g /Pa", p.epsilon_per_pa);
      return std::string(text);
    };
    std::snprintf(name, sizeof name, "gliderflight dynamic (C_D0 %.4f, m_g %.3f kg%s; 10-35 dbar)", fitted[0].cd0,
                  fitted[0].mass_kg, epsilon_text(fitted[0]).c_str());
    row(name, gf[0]);
    std::snprintf(name, sizeof name, "gliderflight steady (C_D0 %.4f, m_g %.3f kg%s; 10-35 dbar)", fitted[1].cd0,
                  fitted[1].mass_kg, epsilon_text(fitted[1]).c_str());
    row(name, gf[1]);
    const double r_every = rms(ours, measured, held) / rms(gf[0], measured, held);
    const double r_kept = rms(ours, measured, held_kept) / rms(gf[0], measured, held_kept);
    std::printf(
        "\nheld-out ratio glider-diagnose / gliderflight dynamic: %.3f every yo, %.3f without the excluded yos "
        "(goal <= 0.8)\n",
        r_every, r_kept);
    // Where the held-out error comes from, both models on the same samples.
    std::printf(
        "\nWhere the held-out error comes from (odd yos without the excluded; error = model - measured, cm/s;\n"
        "share = of the model's squared error; alpha = mean angle of attack, deg: implied by the measured speed and\n"
        "depth rate, asin(w/U) - |pitch|, and each model's own):\n\n"
        "| part | samples | glider-diagnose RMS / mean / share | gliderflight dynamic RMS / mean / share | alpha "
        "measured / glider-diagnose / gliderflight |\n|---|---|---|---|---|\n");
    for (const auto& b : glider::science::speed_error_breakdown(scored, held_kept)) {
      char samples_text[48];
      if (b.samples[0] == b.samples[1]) {
        std::snprintf(samples_text, sizeof samples_text, "%zu", b.samples[0]);
      } else {
        std::snprintf(samples_text, sizeof samples_text, "%zu / %zu", b.samples[0], b.samples[1]);
      }
      std::printf("| %s | %s | %.2f / %+.2f / %.2f | %.2f / %+.2f / %.2f | %.1f / %.1f / %.1f |\n", b.part.c_str(),
                  samples_text, 100.0 * b.rms_m_s[0], 100.0 * b.mean_m_s[0], b.share[0], 100.0 * b.rms_m_s[1],
                  100.0 * b.mean_m_s[1], b.share[1], b.alpha_measured_deg, b.alpha_model_deg[0], b.alpha_model_deg[1]);
    }
    // The part no flight model can take: samples whose DVL speed implies no
    // angle of attack (and, with every yo, the excluded yos). A model exact
    // everywhere else and as wrong as glider-diagnose there scores this.
    auto bound = [&](const std::vector<bool>& use) {
      double kept = 0.0, reference = 0.0;
      for (std::size_t i = 0; i < scored.size(); ++i) {
        if (!use[i]) continue;
        const auto& s = scored[i];
        const double e = s.model_m_s[0] - s.measured_m_s, g = s.model_m_s[1] - s.measured_m_s;
        if (!std::isfinite(e + g)) continue;
        reference += g * g;
        const double alpha = glider::science::implied_alpha_deg(s.measured_m_s, s.depth_rate_measured_m_s, s.pitch_rad);
        if (excluded.count(s.yo) > 0 || !(alpha >= glider::science::kNoLiftAlphaDeg)) kept += e * e;
      }
      return std::sqrt(kept / reference);
    };
    std::printf(
        "\nA model exact wherever the DVL implies an angle of attack >= %.0f deg (outside the excluded yos), as wrong "
        "as glider-diagnose elsewhere: %.3f of gliderflight dynamic every yo, %.3f without the excluded yos\n",
        glider::science::kNoLiftAlphaDeg, bound(held), bound(held_kept));
    return static_cast<int>(glider::cli::kOk);
  });
}
