// SPDX-License-Identifier: Apache-2.0
// Health on a SIL deployment's decimated .sbd files with a hidden fault,
// updated one surfacing at a time through its state file, as the shore runs
// it: the fault is alerted within 3 surfacings of its onset, sized within
// 20 % with an interval that covers it, and nothing is alerted before it.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "glider/health/health.hpp"
#include "sil_deployment.hpp"

using namespace glider;

namespace {

constexpr double kHoursApart = 8.0;

std::string fresh_dir(const std::string& name) {
  const std::string dir = std::string(GLIDER_TEST_OUTPUT_DIR) + "/health/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

const health::Alert* alert_of(const health::HealthRun& run, health::HealthEffect e) {
  for (const health::Alert& a : run.assessment.alerts) {
    if (a.effect == e) return &a;
  }
  return nullptr;
}

// Flies `surfacings`, updating health after each; returns the surfacing at
// which `effect` was first alerted (-1: never) and checks that no alert was
// raised before `onset`.
int fly_and_watch(const std::string& dir, const health_sil::FaultPlan& plan, int surfacings, int onset,
                  health::HealthEffect effect, health::HealthRun& last) {
  int detected = -1;
  for (int k = 0; k < surfacings; ++k) {
    const std::string error = health_sil::fly_surfacing(dir + "/sbd", plan, k, kHoursApart, 500 + k);
    CHECK_TEXT(error.empty(), error.c_str());
    last = health::update_health(health_sil::health_options(dir, kHoursApart));
    CHECK_TEXT(last.measured <= 2, "an update measured more than the new surfacing's segments");
    for (const health::Alert& a : last.assessment.alerts) {
      if (k < onset) FAIL(("surfacing " + std::to_string(k) + ": alert before the fault: " + a.message).c_str());
    }
    if (detected < 0 && alert_of(last, effect) != nullptr) detected = k;
  }
  return detected;
}

// Flies the fault in a fresh folder `name`, checks it is first alerted
// within 3 surfacings of `onset` (and nothing before) and returns its alert
// at the last surfacing (nullptr: none, already failed).
const health::Alert* alerted_within_three(const std::string& name, const health_sil::FaultPlan& plan, int surfacings,
                                          int onset, health::HealthEffect effect, health::HealthRun& run) {
  const int detected = fly_and_watch(fresh_dir(name), plan, surfacings, onset, effect, run);
  const std::string text =
      name + " from surfacing " + std::to_string(onset) + ": first alerted at surfacing " + std::to_string(detected);
  UT_PRINT(text.c_str());
  CHECK_TEXT(detected >= onset && detected <= onset + 2, text.c_str());
  const health::Alert* a = alert_of(run, effect);
  CHECK(a != nullptr);
  UT_PRINT(a->message.c_str());
  return a;
}

// A step alert sized within 20 % of `truth`, its interval covering it.
void check_step_sized(const health::Alert& a, double truth) {
  STRCMP_EQUAL("step", a.kind.c_str());
  DOUBLES_EQUAL(truth, a.size, 0.2 * std::abs(truth));
  CHECK_TEXT(a.low <= truth && truth <= a.high, a.message.c_str());
}

}  // namespace

TEST_GROUP(HealthBuoyancyStep){};

TEST(HealthBuoyancyStep, AlertedWithinThreeSurfacingsAndSized) {
  health_sil::FaultPlan plan;
  plan.step_g = -55.0;  // heavier: a leak, or a gained weight
  plan.step_at = 4;
  health::HealthRun run;
  const health::Alert* a =
      alerted_within_three("buoyancy_step", plan, 8, plan.step_at, health::HealthEffect::kBuoyancyOffset, run);
  check_step_sized(*a, plan.step_g);
  CHECK_EQUAL(1u, run.assessment.alerts.size());
}

TEST_GROUP(HealthFinHalved){};

TEST(HealthFinHalved, AlertedWithinThreeSurfacingsAndSized) {
  health_sil::FaultPlan plan;
  plan.fin_factor = 0.5;
  plan.fin_at = 3;
  health::HealthRun run;
  const health::Alert* a =
      alerted_within_three("fin_halved", plan, 7, plan.fin_at, health::HealthEffect::kFinEffectiveness, run);
  // The truth: halved, a change of -0.5 of the level before (a relative rule).
  CHECK(a->relative);
  const double truth = plan.fin_factor - 1.0;
  DOUBLES_EQUAL(truth, a->size, 0.2 * std::abs(truth));
  // The interval covers the truth: the heading plane reads m_fin as the .sbd
  // stored it (held where unchanged, a line where it moved), not held to the
  // next reading (that read 0.92 before, 0.50 after: -46 % [-49, -42]).
  CHECK_TEXT(a->low <= truth && truth <= a->high && a->high < 0.0, a->message.c_str());
}

TEST_GROUP(HealthPumpLag){};

// Air in the oil: the bladder follows the pump 30 s late from surfacing 3 on
// (the SIL's lag is 0 before). The pump-lag rule (a step of 15 s) is alerted
// within 3 surfacings with the size within 20 % and its interval covering it.
TEST(HealthPumpLag, AlertedWithinThreeSurfacingsAndSized) {
  health_sil::FaultPlan plan;
  plan.pump_lag_s = 30.0;
  plan.pump_lag_at = 3;
  health::HealthRun run;
  const health::Alert* a =
      alerted_within_three("pump_lag", plan, 7, plan.pump_lag_at, health::HealthEffect::kPumpLag, run);
  check_step_sized(*a, plan.pump_lag_s);
}
