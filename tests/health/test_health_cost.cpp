// SPDX-License-Identifier: Apache-2.0
// One surfacing's health update costs well under the 1 s of CPU: a
// SIL surfacing's decimated .sbd (a 3 h box of yos, the surface tail) is
// measured, assessed and its state written. The update's cost is the
// vertical plane's flights (docs/health.md, "Cost"): before the 2 s RK4 step
// and the exp guard of model::first_order_lag_after these two updates cost
// 1.07 and 0.52 s of CPU, after them 0.59 and 0.34 s.
#include <CppUTest/TestHarness.h>

#include <ctime>
#include <filesystem>
#include <string>

#include "glider/health/health.hpp"
#include "sil_deployment.hpp"

using namespace glider;

namespace {

// CPU seconds of this process (the test runs one thread): the machine's
// load changes the wall time, hardly the CPU time.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

TEST_GROUP(HealthCost){};

TEST(HealthCost, OneSurfacingUpdateWellUnderOneSecondOfCpu) {
  const std::string dir = std::string(GLIDER_TEST_OUTPUT_DIR) + "/health/cost";
  std::filesystem::remove_all(dir);
  // Two surfacings (seeds 700, 701): two updates, each measuring its own.
  double worst = 0.0;
  for (int k = 0; k < 2; ++k) {
    const std::string error = health_sil::fly_surfacing(dir + "/sbd", {}, k, 8.0, 700 + k);
    CHECK_TEXT(error.empty(), error.c_str());
    const double cpu0 = cpu_seconds();
    const health::HealthRun run = health::update_health(health_sil::health_options(dir, 8.0));
    const double cpu = cpu_seconds() - cpu0;
    CHECK_EQUAL(2u, run.measured);
    CHECK(run.segments.front().judged);
    const std::string text = "surfacing " + std::to_string(k) + ": update " + std::to_string(cpu) + " s of CPU";
    UT_PRINT(text.c_str());
    worst = std::max(worst, cpu);
  }
  // 0.8 s: the 1 s goal with a fifth to spare (the old code: 1.07 s).
  CHECK_TEXT(worst < 0.8, ("an update cost " + std::to_string(worst) + " s of CPU (at most 0.8)").c_str());
}
