// SPDX-License-Identifier: Apache-2.0
// The comms speed figure (docs/comms.md, Speed): the 30-day waypoint
// mission (boards/missions/month_waypoints, a surfacing every 4 h) flown in SIL
// without comms and with the simulated modem and link calling an in-process
// shore at every surfacing (the setup of the test comms.CommsMonth), CPU time
// of each run and their ratio. Runs alternate (without, with, without, ...) so
// a neighbour's load hits both alike; the least CPU time of each is the figure.
// `--only without|with` flies one run (for callgrind's instruction counts:
// `./glider benchmark` collects only inside glider::sil::run_scenario).
//     bench_comms_month [--days 30] [--repeat 3] [--only without|with]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

#include "glider/firmware/app/mission_setup.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"

using namespace glider;

namespace {

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

struct Run {
  double cpu_s = 0.0;
  sil::ScenarioResult result;
};

Run fly(const model::VehicleParams& vehicle, const fw::FlightSoftwareConfig& mission, sil::ScenarioOptions options,
        bool with_comms) {
  sil::FakeShore shore;
  shore.script = {{10.0, "whoru\r"}};
  if (with_comms) {
    options.comms.emplace();
    std::snprintf(options.comms->config.vehicle_name, 40, "unit_345");
    std::snprintf(options.comms->config.primary_number, 40, "0088160000519");
    options.comms->far_end = &shore;  // the default link model: 90 % sky, 90 % of calls connect, drops
  }
  Run run;
  const double t0 = cpu_s();
  run.result = sil::run_scenario(vehicle, mission, options);
  run.cpu_s = cpu_s() - t0;
  return run;
}

int usage(const char* why) {
  std::fprintf(stderr,
               "bench_comms_month: %s\nusage: bench_comms_month [--days 1..30] [--repeat 1..10] "
               "[--only without|with]\n",
               why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  double days = 30.0;
  int repeat = 3;
  std::string only;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return usage(("missing value after " + arg).c_str());
    const char* value = argv[++i];
    char* end = nullptr;
    if (arg == "--days") {
      days = std::strtod(value, &end);
      if (*end != '\0' || !(days >= 1.0 && days <= 30.0)) return usage("--days: a number in [1, 30]");
    } else if (arg == "--repeat") {
      repeat = static_cast<int>(std::strtol(value, &end, 10));
      if (*end != '\0' || repeat < 1 || repeat > 10) return usage("--repeat: an integer in [1, 10]");
    } else if (arg == "--only") {
      only = value;
      if (only != "without" && only != "with") return usage("--only: without or with");
    } else {
      return usage(("unknown option " + arg).c_str());
    }
  }

  const model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  sil::ScenarioOptions options;
  const fw::app::VehicleSetup setup = sil::vehicle_setup(vehicle, options.fitted, 200.0, false, 1025.0);
  const fw::app::PreparedMission prepared =
      fw::app::prepare_mission(GLIDER_SOURCE_DIR "/boards/missions/month_waypoints/missions/month.mi", setup, {});
  if (!prepared.config) {
    std::fprintf(stderr, "bench_comms_month: the month mission did not load\n");
    return 1;
  }
  options.max_sim_time_s = days * 86400.0;

  if (!only.empty()) {
    const Run run = fly(vehicle, *prepared.config, options, only == "with");
    std::printf("%s comms, %g days: %.2f s CPU, %u surfacings, %u calls connected\n", only.c_str(), days, run.cpu_s,
                run.result.comms.surfacings, run.result.comms.calls_connected);
    return run.result.error.empty() ? 0 : 1;
  }
  std::vector<double> without_s;
  std::vector<double> with_s;
  Run with;
  for (int k = 0; k < repeat; ++k) {
    const Run plain = fly(vehicle, *prepared.config, options, false);
    with = fly(vehicle, *prepared.config, options, true);
    if (!plain.result.error.empty() || !with.result.error.empty()) {
      std::fprintf(stderr, "bench_comms_month: a run failed: %s%s\n", plain.result.error.c_str(),
                   with.result.error.c_str());
      return 1;
    }
    without_s.push_back(plain.cpu_s);
    with_s.push_back(with.cpu_s);
    std::printf("  run %d: %.2f s CPU without comms, %.2f s with\n", k + 1, plain.cpu_s, with.cpu_s);
  }
  double best_without = without_s[0];
  double best_with = with_s[0];
  for (int k = 1; k < repeat; ++k) {
    best_without = std::min(best_without, without_s[static_cast<std::size_t>(k)]);
    best_with = std::min(best_with, with_s[static_cast<std::size_t>(k)]);
  }
  const auto& c = with.result.comms;
  std::printf("%g days, %u surfacings, %u calls connected, %u without a call, %u drops, %u dialogs printed\n", days,
              c.surfacings, c.calls_connected, c.surfacings_without_call, c.carrier_drops, c.dialogs_printed);
  const double ratio = best_with / best_without;
  std::printf("CPU time (least of %d): %.2f s without comms, %.2f s with: ratio x%.2f, %s the issue's bound x2\n",
              repeat, best_without, best_with, ratio, ratio <= 2.0 ? "within" : "OVER");
  return 0;
}
