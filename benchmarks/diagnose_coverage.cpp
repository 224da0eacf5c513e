// SPDX-License-Identifier: Apache-2.0
// bench_diagnose_coverage: how far `./glider diagnose` can be trusted, measured
// over many seeded draws. Each draw flies the SIL with hidden effects (values
// drawn from realistic ranges), thins the log like a real Slocum log, and
// hands only the CSV to the diagnosis; per case it tabulates how often the
// hidden effect is named, its value error, the spurious findings and how often
// the 95 % interval holds the truth. A statistics campaign, not a unit test:
// a fast seeded subset of the same cases is in tests/diagnose.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "diagnose_sampling.hpp"
#include "glider/cli/tool.hpp"
#include "glider/diagnose/diagnose.hpp"
#include "glider/firmware/app/mission_setup.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/environment.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/units.hpp"
#include "hidden_truth.hpp"

namespace {

using glider::diagnose::Effect;
namespace model = glider::model;
namespace diagnose = glider::diagnose;

using glider::hidden::deepest_ctd_depth;
using glider::hidden::glide_mean_vertical_velocity;
using glider::hidden::ts_water;
using glider::hidden::uniform;
double sign(std::mt19937_64& rng) { return (rng() % 2) != 0U ? 1.0 : -1.0; }

// One hidden-effect flight: what is flown, and the truth to compare with.
struct Draw {
  model::VehicleParams flown;
  model::Environment water = model::still_water(1025.0);
  double dive_to_m = 80.0;
  std::map<Effect, double> truth;  // hidden effects; filled after the flight where the log tells (w, density)
  bool stratified = false;         // the log's CTD sees stratified water: water_density is expected
  bool trim_at_median_temperature = false;
};

struct Result {
  std::string case_id;
  std::uint64_t seed = 0;
  bool ok = false;  // flown and diagnosed
  std::string error;
  std::map<Effect, double> truth;
  diagnose::Diagnosis diagnosis;
  bool stratified = false;
};

struct Setup {
  std::string source_dir, out_dir;
  model::VehicleParams nominal;
  diagnose::DiagnoseOptions options;
  glider::hidden::Sampling sampling = glider::hidden::Sampling::kSlocum;
  std::string sampling_name = "slocum";
};

std::string flight_log(const Setup& s, const Draw& d, const std::string& name, std::uint64_t seed) {
  // The mission as glider-sil prepares it (the flight application's one mission entry; its
  // default working depth), the firmware knowing the nominal vehicle; then the case's yos
  // and depth, checked again.
  glider::sil::ScenarioOptions options;
  options.seed = seed;
  options.environment = d.water;
  const glider::fw::app::PreparedMission prepared = glider::fw::app::prepare_mission(
      s.source_dir + "/boards/missions/demo_yo.toml",
      glider::sil::vehicle_setup(s.nominal, options.fitted, 100.0, false, d.water.water.at(0.0, 0.0).density_kg_m3),
      {});
  if (!prepared.config) throw std::runtime_error(name + ": " + prepared.refusal);
  glider::fw::FlightSoftwareConfig config = *prepared.config;
  config.mission.yos = 6;
  config.mission.dive_to_m = d.dive_to_m;
  config.mission.max_depth_m = d.dive_to_m + 15.0;
  if (const std::string problem = glider::fw::validate(config); !problem.empty()) {
    throw std::runtime_error(name + ": " + problem);
  }
  options.logged_vehicle = s.nominal;
  // Rows 2-5 s apart, sci_* gaps, surface gaps: like a real Slocum log.
  options.log_gaps.enabled = s.sampling == glider::hidden::Sampling::kSlocum;
  options.log_path = s.out_dir + "/" + name + ".csv";
  const glider::sil::ScenarioResult flight = glider::sil::run_scenario(d.flown, config, options);
  if (!flight.completed) throw std::runtime_error(name + ": the SIL flight did not complete: " + flight.error);
  return options.log_path;
}

// The case's hidden effects drawn from the ranges of the hidden-effect tests.
Draw draw_case(const std::string& id, const Setup& s, std::mt19937_64& rng) {
  Draw d;
  d.flown = s.nominal;
  const auto add = [&](const std::string& one) {
    if (one == "buoyancy_offset") {
      const double grams = uniform(rng, 25.0, 60.0) * sign(rng);
      d.flown.buoyancy_offset_kg += grams * 1e-3;
      d.truth[Effect::kBuoyancyOffset] = grams;
    } else if (one == "drag_change") {
      const double ratio = uniform(rng, 1.15, 1.5);
      d.flown.hydro.cd0 *= ratio;
      d.truth[Effect::kDragChange] = ratio;
    } else if (one == "hull_compressibility") {
      const double eps = uniform(rng, 1.5e-10, 3e-10);
      d.flown.hull_compressibility_per_pa = eps;
      d.dive_to_m = 180.0;
      d.truth[Effect::kHullCompressibility] = eps;
    } else if (one == "pitch_trim_offset") {
      const double inches = uniform(rng, 0.05, 0.15) * sign(rng);
      d.flown.battery.x_at_zero_m += glider::in_to_m(inches);
      d.truth[Effect::kPitchTrimOffset] = inches;
    } else if (one == "pump_lag") {
      const double lag_s = uniform(rng, 5.0, 15.0);
      d.flown.ballast.lag_s = lag_s;
      d.truth[Effect::kPumpLag] = lag_s;
    } else if (one == "lift_change") {
      const double ratio = (rng() % 2) != 0U ? uniform(rng, 0.65, 0.85) : uniform(rng, 1.25, 1.5);
      d.flown.hydro.cl_alpha *= ratio;
      d.flown.hydro.cl_alpha_abs_alpha *= ratio;
      d.truth[Effect::kLiftChange] = ratio;
    } else if (one == "vertical_water_velocity") {
      const double w = uniform(rng, 0.02, 0.04) * sign(rng);
      d.water = glider::hidden::vertical_velocity_layer(w);
      d.truth[Effect::kVerticalWaterVelocity] = 0.0;  // the log's mean over the glides, after the flight
    } else if (one == "water_density") {
      const double t_top = uniform(rng, 16.0, 22.0), t_bottom = uniform(rng, 8.0, 12.0);
      d.water = ts_water({{0.0, t_top, 34.5}, {15.0, t_top, 34.5}, {60.0, t_bottom, 35.0}});
      d.stratified = true;
      d.truth[Effect::kWaterDensity] = 0.0;  // at the deepest CTD sample, after the flight
    } else if (one == "thermal_expansion") {
      const double expansion = uniform(rng, 2e-5, 7e-5);
      const double t_top = uniform(rng, 17.0, 22.0), t_bottom = uniform(rng, 6.0, 9.0);
      d.water = ts_water({{0.0, t_top, 35.0}, {15.0, t_top, 35.0}, {50.0, t_bottom, 35.0}});
      d.flown.hull_thermal_expansion_per_k = expansion;
      d.dive_to_m = 100.0;
      d.stratified = true;
      d.trim_at_median_temperature = true;
      d.truth[Effect::kThermalExpansion] = expansion;
    } else if (one != "none") {
      throw std::runtime_error("unknown case '" + one + "'");
    }
  };
  for (std::size_t start = 0;;) {  // pairs are "a+b"
    const std::size_t plus = id.find('+', start);
    add(id.substr(start, plus == std::string::npos ? std::string::npos : plus - start));
    if (plus == std::string::npos) break;
    start = plus + 1;
  }
  return d;
}

// The truths only the flown log knows: the mean vertical water velocity over
// the glides, and the density anomaly at the deepest CTD sample.
void truth_from_log(const glider::flightlog::FlightLog& log, const Draw& d, std::map<Effect, double>& truth) {
  if (truth.contains(Effect::kVerticalWaterVelocity)) {
    truth[Effect::kVerticalWaterVelocity] = glide_mean_vertical_velocity(log);
  }
  if (truth.contains(Effect::kWaterDensity)) {
    truth[Effect::kWaterDensity] = d.water.water.at(deepest_ctd_depth(log), 0.0).density_kg_m3 - 1025.0;
  }
}

Result run_draw(const Setup& s, const std::string& case_id, std::uint64_t seed) {
  Result r;
  r.case_id = case_id;
  r.seed = seed;
  std::mt19937_64 rng(seed);
  try {
    Draw d = draw_case(case_id, s, rng);
    std::string name = case_id + "_" + std::to_string(seed);
    if (s.sampling != glider::hidden::Sampling::kSlocum) name += "_1hz";
    std::replace(name.begin(), name.end(), '+', '-');
    if (d.trim_at_median_temperature) {  // trimmed where it flies, as a pilot ballasts
      d.flown.hull_reference_temperature_c =
          diagnose::prepare_observations(glider::flightlog::read_flight_log(flight_log(s, d, name + "_trim", seed)))
              .track.median_temperature_c;
    }
    const glider::flightlog::FlightLog log =
        glider::hidden::resampled(glider::flightlog::read_flight_log(flight_log(s, d, name, seed)), s.sampling, seed);
    r.truth = d.truth;
    r.stratified = d.stratified;
    truth_from_log(log, d, r.truth);
    r.diagnosis = diagnose::diagnose(s.nominal, diagnose::prepare_observations(log), s.options);
    r.ok = true;
  } catch (const std::exception& error) {
    r.error = error.what();
  }
  return r;
}

struct Tally {
  int runs = 0, failed = 0, named = 0, cause = 0, spurious_logs = 0, spurious = 0, covered = 0, valued = 0;
  std::vector<double> abs_error;  // per hidden effect found
  std::vector<std::string> examples;
};

bool is_spurious(const diagnose::Finding& f, const Result& r) {
  if (r.truth.contains(f.effect)) return false;
  // The measured density is an input, not a claim: expected in stratified water.
  return !(f.effect == Effect::kWaterDensity && r.stratified);
}

void add(Tally& t, const Result& r) {
  ++t.runs;
  if (!r.ok) {
    ++t.failed;
    if (t.examples.size() < 3) t.examples.push_back(r.error);
    return;
  }
  bool all_named = true;
  for (const auto& [effect, truth] : r.truth) {
    const diagnose::Finding* f = nullptr;
    for (const auto& finding : r.diagnosis.findings) {
      if (finding.effect == effect) f = &finding;
    }
    if (f == nullptr) {
      all_named = false;
      continue;
    }
    t.abs_error.push_back(std::abs(f->value - truth));
    if (!f->fitted) continue;  // a measured input has no interval to cover
    ++t.valued;
    if (f->ci95_low <= truth && truth <= f->ci95_high) ++t.covered;
  }
  if (all_named) ++t.named;
  // The cause: the first finding that is a claim (the measured density is an
  // input, ranked first in stratified water) must be a hidden effect.
  const diagnose::Finding* first_claim = nullptr;
  for (const auto& f : r.diagnosis.findings) {
    if (first_claim == nullptr && (f.fitted || r.truth.contains(f.effect))) first_claim = &f;
  }
  if (r.truth.empty() ? first_claim == nullptr : first_claim != nullptr && r.truth.contains(first_claim->effect)) {
    ++t.cause;
  }
  int extra = 0;
  for (const auto& f : r.diagnosis.findings) extra += is_spurious(f, r) ? 1 : 0;
  t.spurious += extra;
  if (extra > 0) {
    ++t.spurious_logs;
    if (t.examples.size() < 3) {
      std::string text = "seed draw: cause " + r.diagnosis.cause + ", extras:";
      for (const auto& f : r.diagnosis.findings) {
        if (is_spurious(f, r)) text += std::string(" ") + diagnose::info(f.effect).id;
      }
      t.examples.push_back(text);
    }
  }
}

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::string percent(int part, int whole) {
  if (whole == 0) return "-";
  char text[16];
  std::snprintf(text, sizeof text, "%.0f %%", 100.0 * part / whole);
  return text;
}

// One line per hidden effect of every diagnosed draw (value and interval
// empty where it was not named): for paired comparisons between samplings.
void write_details(const std::string& path, const std::vector<Result>& results) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (out == nullptr) throw std::runtime_error("cannot write " + path);
  std::fprintf(out, "case,seed,effect,truth,value,ci95_low,ci95_high,findings\n");
  for (const Result& r : results) {
    if (!r.ok) continue;
    std::string findings;
    for (const auto& f : r.diagnosis.findings) {
      if (!findings.empty()) findings += ' ';
      findings += diagnose::info(f.effect).id;
    }
    for (const auto& [effect, truth] : r.truth) {
      std::fprintf(out, "%s,%llu,%s,%.9g", r.case_id.c_str(), static_cast<unsigned long long>(r.seed),
                   diagnose::info(effect).id, truth);
      const diagnose::Finding* f = nullptr;
      for (const auto& finding : r.diagnosis.findings) {
        if (finding.effect == effect) f = &finding;
      }
      if (f != nullptr) {
        std::fprintf(out, ",%.9g,%.9g,%.9g", f->value, f->ci95_low, f->ci95_high);
      } else {
        std::fprintf(out, ",,,");
      }
      std::fprintf(out, ",%s\n", findings.c_str());
    }
  }
  std::fclose(out);
}

}  // namespace

int main(int argc, char** argv) {
  glider::cli::Tool tool("bench_diagnose_coverage",
                         "Named, value error, spurious findings and 95 % coverage of "
                         "./glider diagnose over seeded hidden-effect SIL logs");
  CLI::App& app = tool.app();
  int draws = 50;
  unsigned jobs = std::max(1U, std::thread::hardware_concurrency());
  std::uint64_t seed = 20261125;
  std::vector<std::string> cases{"none",
                                 "buoyancy_offset",
                                 "drag_change",
                                 "hull_compressibility",
                                 "pitch_trim_offset",
                                 "pump_lag",
                                 "lift_change",
                                 "vertical_water_velocity",
                                 "water_density",
                                 "thermal_expansion",
                                 "buoyancy_offset+drag_change",
                                 "drag_change+pump_lag",
                                 "buoyancy_offset+hull_compressibility"};
  Setup setup;
  setup.source_dir = GLIDER_SOURCE_DIR;
  setup.out_dir = (std::filesystem::temp_directory_path() / "glider_diagnose_coverage").string();
  tool.add_integer("--draws", draws, 1, 100000, "", "draws per case");
  tool.add_integer("--jobs", jobs, 1, 256, "", "draws flown and diagnosed at once");
  // Seeds up to seed + draws stay in 64 bits.
  tool.add_integer("--seed", seed, 0, glider::cli::kMaxSeed - 100000, "", "draw i of a case uses seed + i");
  app.add_option("--cases", cases, "cases: effect ids, 'a+b' pairs, 'none' (clean logs)")->delimiter(',');
  app.add_option("--out", setup.out_dir, "directory for the SIL logs");
  std::string intervals = "lag1";
  app.add_option("--intervals", intervals, "how the diagnosis's intervals respect serial correlation")
      ->check(CLI::IsMember({"glides", "yos", "lag1"}));
  std::string details;
  app.add_option("--details", details, "CSV file: every draw's hidden effects, truth, value and interval");
  app.add_option("--sampling", setup.sampling_name,
                 "slocum: rows thinned by the SIL writer; 1hz; rows: a 1 Hz flight thinned afterwards; "
                 "pitch/ballast/battpos: 1 Hz with that input reconstructed from the thinned rows")
      ->check(CLI::IsMember({"slocum", "1hz", "rows", "pitch", "ballast", "battpos"}));
  return tool.run(argc, argv, [&]() -> int {
    setup.sampling = glider::hidden::sampling_from(setup.sampling_name);
    std::filesystem::create_directories(setup.out_dir);
    setup.options.intervals = intervals == "yos"      ? diagnose::DiagnoseOptions::Intervals::kYos
                              : intervals == "glides" ? diagnose::DiagnoseOptions::Intervals::kGlides
                                                      : diagnose::DiagnoseOptions::Intervals::kLag1;
    setup.nominal = model::load_vehicle_file(setup.source_dir + "/boards/vehicles/slocum_we01.toml");
    std::vector<std::pair<std::string, std::uint64_t>> work;
    for (const std::string& c : cases) {
      for (int i = 0; i < draws; ++i) work.emplace_back(c, seed + static_cast<std::uint64_t>(i));
    }
    std::vector<Result> results(work.size());
    std::atomic<std::size_t> next{0};
    std::mutex print;
    std::vector<std::thread> pool;
    for (unsigned j = 0; j < jobs; ++j) {
      pool.emplace_back([&] {
        for (std::size_t k = next++; k < work.size(); k = next++) {
          results[k] = run_draw(setup, work[k].first, work[k].second);
          const std::lock_guard<std::mutex> lock(print);
          std::fprintf(stderr, "\r%zu of %zu draws", k + 1, work.size());
        }
      });
    }
    for (std::thread& t : pool) t.join();
    std::fprintf(stderr, "\n");

    std::printf(
        "| case | logs | named | cause first | median abs error | spurious findings (logs) | 95 %% coverage |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    std::map<std::string, Tally> tallies;
    for (const Result& r : results) add(tallies[r.case_id], r);
    for (const std::string& c : cases) {
      const Tally& t = tallies[c];
      char error[32] = "-";
      if (!t.abs_error.empty()) std::snprintf(error, sizeof error, "%.3g", median(t.abs_error));
      std::printf("| %s | %d%s | %s | %s | %s | %d (%s) | %s |\n", c.c_str(), t.runs,
                  t.failed ? (" (" + std::to_string(t.failed) + " failed)").c_str() : "",
                  percent(t.named, t.runs - t.failed).c_str(), percent(t.cause, t.runs - t.failed).c_str(), error,
                  t.spurious, percent(t.spurious_logs, t.runs - t.failed).c_str(),
                  percent(t.covered, t.valued).c_str());
    }
    if (!details.empty()) write_details(details, results);
    for (const std::string& c : cases) {
      for (const std::string& e : tallies[c].examples) std::printf("  %s: %s\n", c.c_str(), e.c_str());
    }
    return static_cast<int>(glider::cli::kOk);
  });
}
