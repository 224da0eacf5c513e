// SPDX-License-Identifier: Apache-2.0
// glider-forecast-bench: the forecast scored on SIL truths (fresh seeds,
// printed) against the baseline "the last depth-averaged current persists"
// (docs/forecast.md, Benchmark). `./glider benchmark forecast` runs it.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "glider/cli/tool.hpp"
#include "glider/firmware/geo.hpp"
#include "glider/forecast/forecast.hpp"
#include "glider/forecast/sil_truth.hpp"
#include "glider/forecast/tide_table.hpp"
#include "glider/sil/portable_random.hpp"

namespace fs = std::filesystem;
namespace fc = glider::forecast;

namespace {

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double at = p * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(at));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

struct Score {
  std::vector<double> position_m, time_s, baseline_position_m, baseline_time_s, wall_s;
  // The truth's place on each forecast's 95 % ellipse (1 its edge; a
  // calibrated ellipse: median 0.48, p90 0.88, beyond 1 in 5 %).
  std::vector<double> ellipse_place;
  int inside_ellipse = 0, cases = 0, aborted = 0;
  // The current the glider measured over the forecast dive (the next
  // surfacing's m_water_vx/vy) against the forecast's, in its sigmas.
  std::vector<double> current_z;
  // The same forecast in the current measured next: the runs steer with what
  // the glider believed, so the water only moves them, by (measured -
  // forecast current) x the forecast dive. What is left is the flight and
  // the timing; the difference is the current estimate's (docs/forecast.md,
  // session 41).
  std::vector<double> measured_current_position_m, current_term_m;
};

double distance_m(double lat1, double lon1, double lat2, double lon2) {
  const glider::fw::LocalFrame frame({lat1, lon1});
  const glider::fw::EastNorth d = frame.to_local({lat2, lon2});
  return std::hypot(d.east_m, d.north_m);
}

// The truth's place on the forecast's 95 % ellipse: <= 1 inside (1 on it).
double ellipse_radius(const fc::Forecast& f, double lat, double lon) {
  const glider::fw::LocalFrame frame({f.lat_deg, f.lon_deg});
  const glider::fw::EastNorth d = frame.to_local({lat, lon});
  const double a = f.ellipse.orientation_deg * M_PI / 180.0;
  const double along = d.east_m * std::sin(a) + d.north_m * std::cos(a);
  const double across = d.east_m * std::cos(a) - d.north_m * std::sin(a);
  const double ma = std::max(f.ellipse.semi_major_m, 1.0), mi = std::max(f.ellipse.semi_minor_m, 1.0);
  return std::sqrt((along * along) / (ma * ma) + (across * across) / (mi * mi));
}

void score_case(const fc::Forecast& f, const fc::TruthSurfacing& next, Score& s, bool print) {
  ++s.cases;
  if (!f.have_surfacing || !f.baseline_ok) {
    ++s.aborted;
    return;
  }
  const double e = distance_m(f.lat_deg, f.lon_deg, next.lat_deg, next.lon_deg);
  const double b = distance_m(f.baseline_lat_deg, f.baseline_lon_deg, next.lat_deg, next.lon_deg);
  s.position_m.push_back(e);
  s.baseline_position_m.push_back(b);
  s.time_s.push_back(std::fabs(f.time_utc_s - next.surfaced_utc_s));
  s.baseline_time_s.push_back(std::fabs(f.baseline_time_utc_s - next.surfaced_utc_s));
  s.wall_s.push_back(f.wall_s);
  const double radius = ellipse_radius(f, next.lat_deg, next.lon_deg);
  if (radius <= 1.0) ++s.inside_ellipse;
  s.ellipse_place.push_back(radius);
  double ze = std::nan(""), zn = std::nan("");
  if (next.have_current) {
    ze = (next.water_vx - f.current.east_m_s) / f.current.sigma_east_m_s;
    zn = (next.water_vy - f.current.north_m_s) / f.current.sigma_north_m_s;
    s.current_z.push_back(ze);
    s.current_z.push_back(zn);
    const double dive_s = f.time_utc_s - f.dive_utc_s;
    const double de = (next.water_vx - f.current.east_m_s) * dive_s,
                 dn = (next.water_vy - f.current.north_m_s) * dive_s;
    const glider::fw::EastNorth truth =
        glider::fw::LocalFrame({f.fix_lat_deg, f.fix_lon_deg}).to_local({next.lat_deg, next.lon_deg});
    s.measured_current_position_m.push_back(std::hypot(f.east_m + de - truth.east_m, f.north_m + dn - truth.north_m));
    s.current_term_m.push_back(std::hypot(de, dn));
  }
  if (print) {
    // The miss in the ellipse's axes, and the forecast's travel from the fix.
    const glider::fw::LocalFrame frame({f.lat_deg, f.lon_deg});
    const glider::fw::EastNorth d = frame.to_local({next.lat_deg, next.lon_deg});
    const double a = f.ellipse.orientation_deg * M_PI / 180.0;
    std::printf(
        "    travel %.0f m toward %.0f deg; ellipse toward %.0f deg; miss %+.0f m along its major axis, %+.0f across\n",
        std::hypot(f.east_m, f.north_m), std::fmod(std::atan2(f.east_m, f.north_m) * 180.0 / M_PI + 360.0, 360.0),
        f.ellipse.orientation_deg, d.east_m * std::sin(a) + d.north_m * std::cos(a),
        d.east_m * std::cos(a) - d.north_m * std::sin(a));
    std::printf(
        "    forecast %6.0f m, %+5.0f s off (baseline %6.0f m, %+5.0f s); ellipse %4.0f x %4.0f m, truth at %.2f of "
        "it; current %s +-%.3f/%.3f m/s, measured next %+.1f/%+.1f sigma; %.2f s\n",
        e, f.time_utc_s - next.surfaced_utc_s, b, f.baseline_time_utc_s - next.surfaced_utc_s, f.ellipse.semi_major_m,
        f.ellipse.semi_minor_m, radius, f.current.method.c_str(), f.current.sigma_east_m_s, f.current.sigma_north_m_s,
        ze, zn, f.wall_s);
    // The speed term: the pitch scale read and its evidence, the drag found.
    std::printf(
        "    speed term: pitch scale %.3f +-%.3f (%d samples), DR speed x%.3f; speed ratio %.3f over %d dives; "
        "drag x%.3f +-%.3f\n",
        f.pitch_scale, f.pitch_scale_sigma, f.pitch_samples, f.pitch_dr_speed_factor, f.glider_speed_ratio,
        f.speed_dives, f.speed_drag_factor, f.speed_drag_sigma);
    // The depth-rate calibration: what it read and whether the runs flew it.
    if (f.depth_rate_have) {
      std::printf(
          "    depth rates: glider %.3f / %.3f m/s, model %.3f / %.3f; %s hull x%.3f of m_pitch, drag x%.3f, "
          "buoyancy %+.1f g (%s)\n",
          f.depth_rate_glider_dive_m_s, f.depth_rate_glider_climb_m_s, f.depth_rate_model_dive_m_s,
          f.depth_rate_model_climb_m_s, f.depth_rate_servo ? "servo:" : "battery fixed:", f.depth_rate_pitch_scale,
          f.depth_rate_drag_factor, 1000.0 * f.depth_rate_buoyancy_kg, f.depth_rate_applied ? "flown" : "not flown");
    }
    // The currents themselves (m/s), to score a current rule without its
    // flights: the forecast's, persistence's and the one measured next.
    std::printf("    current forecast %+.3f %+.3f, persistence %+.3f %+.3f, measured next %+.3f %+.3f m/s\n",
                f.current.east_m_s, f.current.north_m_s, f.baseline_current.east_m_s, f.baseline_current.north_m_s,
                next.have_current ? next.water_vx : std::nan(""), next.have_current ? next.water_vy : std::nan(""));
    if (next.have_current) {
      std::printf("    in the current measured next: %.0f m off (the current's term %.0f m of the %.0f)\n",
                  s.measured_current_position_m.back(), s.current_term_m.back(), e);
    }
  }
}

void print_table(const char* what, const Score& s) {
  std::printf("\n%s: %d forecasts (%d without a surfacing)\n", what, s.cases, s.aborted);
  std::printf("| | position median | position p90 | time median |\n|---|---|---|---|\n");
  std::printf("| forecast | %.2f km | %.2f km | %.1f min |\n", percentile(s.position_m, 0.5) / 1000.0,
              percentile(s.position_m, 0.9) / 1000.0, percentile(s.time_s, 0.5) / 60.0);
  std::printf("| baseline (last current persists) | %.2f km | %.2f km | %.1f min |\n",
              percentile(s.baseline_position_m, 0.5) / 1000.0, percentile(s.baseline_position_m, 0.9) / 1000.0,
              percentile(s.baseline_time_s, 0.5) / 60.0);
  if (!s.measured_current_position_m.empty()) {
    std::printf("| forecast in the current measured next (flight and timing left) | %.2f km | %.2f km | |\n",
                percentile(s.measured_current_position_m, 0.5) / 1000.0,
                percentile(s.measured_current_position_m, 0.9) / 1000.0);
  }
  const double gain = 1.0 - percentile(s.position_m, 0.5) / percentile(s.baseline_position_m, 0.5);
  std::printf(
      "median position error %.0f %% better than the baseline; truth inside the 95 %% ellipse in %d of %zu, its "
      "place on it median %.2f, p90 %.2f (calibrated: 0.48, 0.88); wall per forecast median %.2f s, max %.2f s\n",
      100.0 * gain, s.inside_ellipse, s.position_m.size(), percentile(s.ellipse_place, 0.5),
      percentile(s.ellipse_place, 0.9), percentile(s.wall_s, 0.5),
      s.wall_s.empty() ? std::nan("") : *std::max_element(s.wall_s.begin(), s.wall_s.end()));
  double z2 = 0.0;
  int within2 = 0;
  for (double z : s.current_z) {
    z2 += z * z;
    within2 += std::fabs(z) <= 1.96 ? 1 : 0;
  }
  std::printf(
      "the current measured over the forecast dive against the forecast's: RMS %.2f sigma, within 1.96 sigma in %d "
      "of %zu components\n",
      s.current_z.empty() ? std::nan("") : std::sqrt(z2 / static_cast<double>(s.current_z.size())), within2,
      s.current_z.size());
}

// The truth's tide as a pilot's tide model would give it: each constituent's
// phase off by +-[phase_lo, phase_hi] deg and its amplitude by a factor 1
// +-[amp_lo, amp_hi] (sizes uniform, signs even, drawn from the truth's seed;
// the same for east and north: a model's error in the tide's timing and
// strength), its stated sigmas `phase_sigma_deg` and `amp_sigma` x amplitude.
fc::TideTable pilots_table(const fc::TideTable& truth, std::uint64_t seed, const double phase_error[2],
                           const double amplitude_error[2], double phase_sigma_deg, double amp_sigma,
                           std::string& said) {
  glider::sil::PortableRandom draw(glider::sil::derived_seed(seed, 0x7469646531ULL));
  fc::TideTable t = truth;
  for (fc::TideConstituent& c : t.constituents) {
    const double dp =
        (draw.uniform() < 0.5 ? -1.0 : 1.0) * (phase_error[0] + (phase_error[1] - phase_error[0]) * draw.uniform());
    const double da = (draw.uniform() < 0.5 ? -1.0 : 1.0) *
                      (amplitude_error[0] + (amplitude_error[1] - amplitude_error[0]) * draw.uniform());
    for (fc::TideComponent* k : {&c.east, &c.north}) {
      k->phase_deg += dp;
      k->amplitude_m_s *= 1.0 + da;
      k->amplitude_sigma_m_s = amp_sigma * k->amplitude_m_s;
      k->phase_sigma_deg = phase_sigma_deg;
    }
    char text[120];
    std::snprintf(text, sizeof text, "%s phase %+.0f deg, amplitude x%.2f", c.name.c_str(), dp, 1.0 + da);
    said += text;
  }
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("glider-forecast-bench", "the forecast against SIL truths, beside the baseline");
  CLI::App& app = tool.app();
  fc::TruthOptions truth_options;
  const fs::path boards = glider::cli::boards_dir();
  std::string mission = (boards / "missions/box_current/missions/box.mi").string();
  std::string vehicle = (boards / "vehicles/slocum_shallow.toml").string();
  std::string out = "forecast-bench";
  std::int64_t seed = -1;
  int truths = 4;
  int from = 2;
  fc::ForecastOptions options;
  options.runs = 200;
  app.add_option("--mission", mission, "the truth's .mi")->capture_default_str();
  app.add_option("--vehicle", vehicle, "nominal vehicle file")->capture_default_str();
  app.add_option("--out", out, "folder for the glider folders")->capture_default_str();
  tool.add_integer("--seed", seed, -1, glider::cli::kMaxSeed, "", "first truth's seed (-1: fresh, printed)");
  tool.add_integer("--truths", truths, 1, 1000, "truths", "SIL truths (one seed each)")->capture_default_str();
  tool.add_integer("--surfacings", truth_options.surfacings, 2, 200, "surfacings", "surfacings per truth")
      ->capture_default_str();
  tool.add_integer("--from", from, 1, 200, "surfacing", "first surfacing forecast from")->capture_default_str();
  tool.add_integer("--runs", options.runs, 1, 100000, "runs", "Monte-Carlo runs per forecast")->capture_default_str();
  tool.add_integer("--threads", options.threads, 1, 64, "threads", "threads per forecast")->capture_default_str();
  std::string prior_mode = "evidence";
  app.add_option("--current-prior", prior_mode, "the forecasts' current prior: evidence, fixed or off")
      ->check(CLI::IsMember({"evidence", "fixed", "off"}))
      ->capture_default_str();
  double prior_position_m = fc::TidalPrior{}.position_sigma_m;
  tool.add_number("--prior-position-sigma", prior_position_m, {0.0, 5000.0, "m"},
                  "the forecasts' prior: each current estimate's position error over its segment (0: the rule off)")
      ->capture_default_str();
  app.add_flag("--speed-correction", options.speed_correction,
               "the forecasts scale the model's drag to the glider's dead-reckoned speed, calibrated or not "
               "(default: only calibrated for its pitch sensor; docs/forecast.md)");
  app.add_flag("!--no-speed-correction", options.speed_correction_calibrated,
               "the forecasts never scale the model's drag");
  app.add_flag("!--no-glider-dead-reckoning", options.glider_dead_reckoning,
               "the forecasts' model firmware dead-reckons as the vehicle file's, not through the pitch sensor");
  app.add_flag("--pitch-calibration", options.pitch_calibration,
               "the forecasts calibrate the glider's dead-reckoned speed for its pitch sensor's scale (off by "
               "default, as glider-forecast)");
  app.add_flag("!--no-depth-rate-calibration", options.depth_rate_calibration,
               "the forecasts fly the vehicle file, not calibrated to the glider's steady-glide depth rates");
  app.add_flag("--depth-rate-drag", options.depth_rate_drag,
               "with the battery fixed the forecasts fly the drag and buoyancy the depth rates read too (as "
               "glider-forecast)");
  app.add_flag("--truth-servo-on-sensor", truth_options.servo_on_sensor,
               "the truths' pitch servo holds the biased sensor's pitch at the mission's (as a real servo does), "
               "not the hull's");
  tool.add_number("--truth-gps-noise", truth_options.gps_noise_m, {0.0, 1000.0, "m"},
                  "the truths' GPS fixes, 1 sigma per axis (the SIL's 3 m; a real glider's fix as it dives and its "
                  "DR's restart can be off by 100 m and more: each current estimate off by that over its dive)")
      ->capture_default_str();
  tool.add_number("--truth-pitch-bias", truth_options.pitch_bias_max, {0.0, 0.5, ""},
                  "the truths' pitch sensor reads (1 + b) x the hull's pitch, b drawn uniform in [-this, this]")
      ->capture_default_str();
  tool.add_number("--truth-drag-sigma", truth_options.drag_sigma, {0.0, 1.0, ""},
                  "the true vehicle's drag off the file's, 1 sigma of its log")
      ->capture_default_str();
  tool.add_number("--truth-drag", truth_options.drag_factor, {0.2, 5.0, ""},
                  "the true vehicle's drag as a factor of the file's (times the drawn one)")
      ->capture_default_str();
  double tide_max = truth_options.tide_amplitude_max_m_s, mean_max = truth_options.mean_current_max_m_s;
  tool.add_number("--tide-max", tide_max, {0.0, 2.0, "m/s"}, "the truths' M2 amplitude is drawn up to this")
      ->capture_default_str();
  tool.add_number("--mean-max", mean_max, {0.0, 2.0, "m/s"}, "the truths' mean current is drawn up to this")
      ->capture_default_str();
  bool tide_pair = false;
  app.add_flag("--tide-table", tide_pair,
               "paired: each forecast again with a tide table (--tide), the truth's M2 with a pilot's tide model's "
               "errors (drawn per truth, printed); both tables printed");
  std::vector<double> phase_error{20.0, 40.0}, amplitude_error{0.2, 0.3};
  app.add_option("--tide-phase-error", phase_error, "the table's phase error's size, drawn in [lo, hi] deg")
      ->expected(2)
      ->delimiter(',')
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str();
  app.add_option("--tide-amplitude-error", amplitude_error,
                 "the table's amplitude error's size, a fraction drawn in [lo, hi]")
      ->expected(2)
      ->delimiter(',')
      ->check(CLI::Range(0.0, 0.9))
      ->capture_default_str();
  double phase_sigma = 30.0, amp_sigma = 0.25;
  tool.add_number("--tide-phase-sigma", phase_sigma, {0.0, 180.0, "deg"}, "the table's stated phase sigma")
      ->capture_default_str();
  tool.add_number("--tide-amplitude-sigma", amp_sigma, {0.0, 3.0, ""},
                  "the table's stated amplitude sigma, a fraction of its amplitude")
      ->capture_default_str();
  double check_km = 0.0;
  tool.add_number("--check-km", check_km, {0.0, 100.0, "km"},
                  "test mode: exit 1 unless every forecast is within this of the truth and the truth of the first "
                  "is inside its ellipse (0: off)");
  return tool.run(argc, argv, [&]() -> int {
    if (seed < 0) {
      seed = static_cast<std::int64_t>(std::random_device{}() % 1000000);
    }
    options.prior.mode = fc::parse_prior_mode(prior_mode);
    options.prior.position_sigma_m = prior_position_m;
    truth_options.tide_amplitude_max_m_s = tide_max;
    truth_options.mean_current_max_m_s = mean_max;
    truth_options.mission = mission;
    truth_options.vehicle = vehicle;
    options.vehicle = vehicle;
    Score score, with_table, first_without, first_with;
    bool ok = true;
    int better = 0, worse = 0;
    for (int k = 0; k < truths; ++k) {
      truth_options.seed = static_cast<std::uint64_t>(seed) + static_cast<std::uint64_t>(k);
      const fc::Truth truth = fc::fly_truth(truth_options);
      std::printf("truth %s: %zu surfacings\n", truth.description.c_str(), truth.surfacings.size());
      for (std::size_t i = static_cast<std::size_t>(from); i + 1 < truth.surfacings.size(); ++i) {
        const fs::path dir =
            fs::path(out) / ("seed" + std::to_string(truth_options.seed)) / ("from" + std::to_string(i));
        fs::remove_all(dir);
        fc::write_glider_folder(truth, truth_options, "simglider", i, dir);
        options.seed = truth_options.seed * 1000 + i;
        const fc::Forecast f = fc::make_forecast(dir, options);
        std::printf("  from surfacing %zu:", i);
        score_case(f, truth.surfacings[i + 1], score, true);
        if (tide_pair) {
          std::string said;
          const fc::TideTable table = pilots_table(truth.tide, truth_options.seed, phase_error.data(),
                                                   amplitude_error.data(), phase_sigma, amp_sigma, said);
          std::ofstream(dir / "tide.toml") << fc::format_tide_table(table, "the bench's pilot table: " + said);
          fc::ForecastOptions tabled = options;
          tabled.tide_table = dir / "tide.toml";
          const fc::Forecast g = fc::make_forecast(dir, tabled);
          std::printf("  the same with the tide table (%s):", said.c_str());
          score_case(g, truth.surfacings[i + 1], with_table, true);
          if (i == static_cast<std::size_t>(from)) {
            score_case(f, truth.surfacings[i + 1], first_without, false);
            score_case(g, truth.surfacings[i + 1], first_with, false);
          }
          if (!score.position_m.empty() && !with_table.position_m.empty() && f.have_surfacing && g.have_surfacing) {
            (with_table.position_m.back() < score.position_m.back() ? better : worse) += 1;
          }
        }
        if (check_km > 0.0 && (!f.have_surfacing || score.position_m.back() > 1000.0 * check_km)) ok = false;
      }
    }
    print_table("SIL truths", score);
    if (tide_pair) {
      print_table("SIL truths with the tide table (the same forecasts, paired)", with_table);
      print_table("the first forecasts (from surfacing --from) without the table", first_without);
      print_table("the first forecasts with the tide table", first_with);
      std::printf("with the table: %d forecasts nearer the truth, %d not (seed %lld)\n", better, worse,
                  static_cast<long long>(seed));
    }
    if (check_km > 0.0 && score.inside_ellipse == 0) ok = false;
    return ok ? 0 : 1;
  });
}
