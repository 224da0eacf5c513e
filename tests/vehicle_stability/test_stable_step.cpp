// SPDX-License-Identifier: Apache-2.0
// Every shipped vehicle gets an integration step its fastest mode allows
// (glider/model/stable_step.hpp): the stiff IIT Madras lab glider a shorter
// one than the default, the Slocum-class vehicles the default unchanged.
#include <CppUTest/TestHarness.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "glider/model/simulator.hpp"
#include "glider/model/stable_step.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

TEST_GROUP(StableStep){};

TEST(StableStep, EveryShippedVehicleStepIsInsideRk4Limits) {
  int vehicles = 0;
  for (const auto& entry : std::filesystem::directory_iterator(GLIDER_SOURCE_DIR "/boards/vehicles")) {
    if (entry.path().extension() != ".toml") continue;
    ++vehicles;
    const VehicleParams v = load_vehicle_file(entry.path().string());
    const GliderSimulator sim(v, Environment{});
    const double fastest = fastest_glide_mode_per_s(sim.dynamics());
    std::printf("\n%s: fastest glide mode %.3f 1/s, step %.3f s", v.name.c_str(), fastest, sim.step_s());
    CHECK_TRUE(fastest > 0.0);  // every shipped vehicle glides at its pump limits
    CHECK_TRUE(sim.step_s() > 0.0 && sim.step_s() <= GliderSimulator::kDefaultStepS);
    CHECK_TRUE(fastest * sim.step_s() <= kMaxLambdaStep * (1.0 + 1e-12));
    if (v.name == "iitm_lab_glider") CHECK_TRUE(sim.step_s() < GliderSimulator::kDefaultStepS);
    if (v.name == "slocum_we01") DOUBLES_EQUAL(GliderSimulator::kDefaultStepS, sim.step_s(), 0.0);
  }
  CHECK_TRUE(vehicles >= 6);
}
