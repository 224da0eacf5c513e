// SPDX-License-Identifier: Apache-2.0
// Scratch study (issue 24/26): one SIL surfacing flown with the 4 s .sbd list
// and with every sensor every cycle; the vertical plane's drag on each, and on
// the full list with m_depth / m_pitch alone decimated in memory.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/observations.hpp"
#include "glider/diagnose/stored_on_change.hpp"
#include "glider/slocum/log_loader.hpp"
#include "sil_deployment.hpp"

using namespace glider;

namespace {

std::string full_list() {
  std::string text = health_sil::read_text(GLIDER_SOURCE_DIR "/tests/health/sbdlist.dat");
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

flightlog::FlightLog load(const std::string& dir, const char* ext) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() == ext) files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return slocum::load_flight_log({files, {}}, {});
}

// Keeps a column's values at most every `every_s` (as the .sbd writer's interval).
flightlog::FlightLog decimate(const flightlog::FlightLog& log, const std::vector<std::string>& which, double every_s) {
  std::vector<flightlog::Column> columns;
  std::size_t time_index = 0;
  const auto& names = log.column_names();
  const auto& time = log.time();
  for (std::size_t c = 0; c < names.size(); ++c) {
    flightlog::Column column = log.column(names[c]);
    if (&log.column(names[c]) == &time) time_index = c;
    if (std::find(which.begin(), which.end(), names[c]) != which.end()) {
      double last = -1e18;
      for (std::size_t i = 0; i < column.size(); ++i) {
        if (!std::isfinite(column[i])) continue;
        if (time[i] - last >= every_s - 1e-6) {
          last = time[i];
        } else {
          column[i] = NAN;
        }
      }
    }
    columns.push_back(std::move(column));
  }
  return flightlog::FlightLog(log.source(), log.metadata(), names, std::move(columns), time_index);
}

bool g_as_stored = true;

double drag_of(const flightlog::FlightLog& raw, bool decimated) {
  const flightlog::FlightLog log = decimated ? diagnose::hold_stored_columns(raw, 900.0, true) : raw;
  diagnose::ObservationOptions oo;
  oo.track.as_stored = g_as_stored;
  const diagnose::Observations obs = diagnose::prepare_observations(log, oo);
  diagnose::DiagnoseOptions options;
  options.fit_only = {diagnose::Effect::kBuoyancyOffset, diagnose::Effect::kDragChange, diagnose::Effect::kPumpLag};
  options.max_step_s = 2.0;
  const diagnose::Diagnosis d = diagnose::diagnose(health_sil::nominal_vehicle(), obs, options);
  for (const auto& f : d.findings) {
    if (f.effect == diagnose::Effect::kDragChange) return f.value;
  }
  return NAN;
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : std::random_device{}() % 1000000000ULL;
  const double factor = argc > 2 ? std::atof(argv[2]) : 1.0;
  std::printf("seed %llu factor %g\n", static_cast<unsigned long long>(seed), factor);
  health_sil::FaultPlan plan;
  plan.drag_per_day = factor - 1.0;
  plan.drag_onset_day = 0.0;
  const std::string base = "/tmp/decim_study/" + std::to_string(seed) + "_" + std::to_string(factor);
  std::filesystem::remove_all(base);
  // k = 24 h apart x 1 surfacing: day 1 -> cd0 x factor.
  std::string e1 = health_sil::fly_surfacing(base + "/sbd", plan, 1, 24.0, seed);
  std::string e2 = health_sil::fly_surfacing(base + "/full", plan, 1, 24.0, seed, full_list());
  if (!e1.empty() || !e2.empty()) {
    std::printf("fly: %s %s\n", e1.c_str(), e2.c_str());
    return 1;
  }
  const flightlog::FlightLog sbd = load(base + "/sbd", ".sbd");
  const flightlog::FlightLog full = load(base + "/full", ".sbd");
  std::printf("rows sbd %zu full %zu\n", sbd.rows(), full.rows());
  if (std::getenv("DUMP") != nullptr) {
    for (const auto* lg : {&sbd, &full}) {
      const auto& t = lg->time();
      const auto* d = lg->find("m_depth");
      const auto* p = lg->find("m_pitch");
      const auto* b = lg->find("m_ballast_pumped");
      for (std::size_t i = 2000; i < 2060 && i < t.size(); ++i)
        std::printf("%.3f %.4f %.5f %.2f\n", t[i] - t[0], (*d)[i], (*p)[i], (*b)[i]);
      std::printf("--\n");
    }
  }
  for (int rule = 0; rule < 2; ++rule) {
    g_as_stored = rule == 1;
    std::printf("rule %s\n", g_as_stored ? "as stored (new)" : "filled rows (old)");
    std::printf("sbd            %.5f\n", drag_of(sbd, true));
    std::printf("full           %.5f\n", drag_of(full, true));
    std::printf("full dec depth %.5f\n", drag_of(decimate(full, {"m_depth"}, 4.0), true));
    std::printf("full dec pitch %.5f\n", drag_of(decimate(full, {"m_pitch"}, 4.0), true));
    std::printf("full dec both  %.5f\n", drag_of(decimate(full, {"m_depth", "m_pitch"}, 4.0), true));
    std::printf("full dec d+p+ballast %.5f\n",
                drag_of(decimate(full, {"m_depth", "m_pitch", "m_ballast_pumped"}, 4.0), true));
    std::printf("full dec d+p+battpos %.5f\n", drag_of(decimate(full, {"m_depth", "m_pitch", "m_battpos"}, 4.0), true));
    std::printf("full dec ballast %.5f\n", drag_of(decimate(full, {"m_ballast_pumped"}, 4.0), true));
    std::printf("full dec all4 %.5f\n",
                drag_of(decimate(full,
                                 {"m_depth", "m_pitch", "m_roll", "m_heading", "c_heading", "m_fin", "c_fin",
                                  "m_battpos", "m_ballast_pumped", "c_ballast_pumped"},
                                 4.0),
                        true));
  }
  return 0;
}
