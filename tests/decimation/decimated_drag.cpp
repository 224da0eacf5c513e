// SPDX-License-Identifier: Apache-2.0
// The vertical plane reads the same drag on a flight's decimated .sbd as on
// the same flight stored every cycle (issues 24 and 26; docs/science.md,
// "Decimated depth, pitch and ballast"). One SIL surfacing (health's box
// mission, cd0 drawn in x1..x1.3) is flown twice with the same seed: once
// writing tests/health/sbdlist.dat (24 sensors, 4 s at most, as health
// receives them), once writing the same sensors every cycle. Each is read as
// health reads it and fitted for drag, buoyancy and pump lag.
//
// The bound: |drag(.sbd) / drag(every cycle) - 1| <= 0.0025. Measured on
// 11 fresh flights at cd0 x1 to x1.26 (docs/science.md, "Decimated depth,
// pitch and ballast read as stored"): the track as stored reads -0.0012 to
// +0.0001 (mean -0.0007, sd 0.00035: the bound is |mean| + 5 sd); the rule
// before (every row's filled value a measurement) -0.0032 to -0.0136 (mean
// -0.0071), outside the bound in 11 of 11. A fresh seed each run, printed;
// GLIDER_TEST_SEED replays it. Exit 0 pass, 1 fail.
#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/diagnose/stored_on_change.hpp"
#include "glider/slocum/log_loader.hpp"
#include "sil_deployment.hpp"

using namespace glider;

namespace {

constexpr double kBound = 0.0025;

// tests/health/sbdlist.dat with every interval dropped: each sensor every cycle.
std::string every_cycle_list() {
  const std::string text = health_sil::read_text(GLIDER_SOURCE_DIR "/tests/health/sbdlist.dat");
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string::npos) eol = text.size();
    std::string line = text.substr(pos, eol - pos);
    if (!line.empty() && line[0] != '#') line = line.substr(0, line.find(' '));
    out += line + "\n";
    pos = eol + 1;
  }
  return out;
}

flightlog::FlightLog load_sbd(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() == ".sbd") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  // As health reads an .sbd: the columns stored on change held between stores.
  return diagnose::hold_stored_columns(slocum::load_flight_log({files, {}}, {}), 900.0, true);
}

// The drag as health's vertical plane fits it (measure.cpp: drag, offset and lag).
double drag_of(const flightlog::FlightLog& log, bool as_stored) {
  diagnose::ObservationOptions observation;
  observation.track.as_stored = as_stored;
  diagnose::DiagnoseOptions options;
  options.fit_only = {diagnose::Effect::kBuoyancyOffset, diagnose::Effect::kDragChange, diagnose::Effect::kPumpLag};
  options.max_step_s = 2.0;
  const diagnose::Diagnosis d =
      diagnose::diagnose(health_sil::nominal_vehicle(), diagnose::prepare_observations(log, observation), options);
  for (const diagnose::Finding& f : d.findings) {
    if (f.effect == diagnose::Effect::kDragChange) return f.value;
  }
  return NAN;
}

}  // namespace

int main() {
  std::uint64_t seed = 0;
  if (const char* given = std::getenv("GLIDER_TEST_SEED"); given != nullptr && *given != '\0') {
    seed = std::strtoull(given, nullptr, 10);
  } else {
    std::random_device device;
    seed = ((static_cast<std::uint64_t>(device()) << 32) ^ device()) % 1000000000ULL;
  }
  std::mt19937_64 rng(seed);
  const double factor = std::uniform_real_distribution<double>(1.0, 1.3)(rng);
  std::printf("decimated drag: seed %" PRIu64 " (replay: GLIDER_TEST_SEED=%" PRIu64 "), cd0 x%.4f\n", seed, seed,
              factor);
  health_sil::FaultPlan plan;  // surfacing 1, a day after the onset: cd0 x factor
  plan.drag_onset_day = 0.0;
  plan.drag_per_day = factor - 1.0;
  const std::string dir = std::string(GLIDER_TEST_OUTPUT_DIR) + "/decimated_drag";
  std::filesystem::remove_all(dir);
  for (const auto& [name, list] :
       {std::pair<std::string, std::string>{"sbd", ""}, {"every_cycle", every_cycle_list()}}) {
    const std::string error = health_sil::fly_surfacing(dir + "/" + name, plan, 1, 24.0, seed, list);
    if (!error.empty()) {
      std::printf("FAIL: flying the %s surfacing: %s\n", name.c_str(), error.c_str());
      return 1;
    }
  }
  const flightlog::FlightLog sbd = load_sbd(dir + "/sbd"), every_cycle = load_sbd(dir + "/every_cycle");
  const double full = drag_of(every_cycle, true), decimated = drag_of(sbd, true);
  const double before = drag_of(sbd, false);
  const double error = decimated / full - 1.0;
  std::printf(
      "drag every cycle %.5f, .sbd as stored %.5f (%+.4f), .sbd rows as measurements (the rule before) %.5f "
      "(%+.4f); bound +-%.4f\n",
      full, decimated, error, before, before / full - 1.0, kBound);
  if (!(std::abs(error) <= kBound)) {
    std::printf("FAIL: the .sbd's drag is %+.4f of the every-cycle flight's (bound +-%.4f)\n", error, kBound);
    return 1;
  }
  return 0;
}
