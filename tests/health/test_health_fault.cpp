// SPDX-License-Identifier: Apache-2.0
// Health on a SIL deployment's decimated .sbd files with a hidden fault,
// updated one surfacing at a time through its state file, as the shore runs
// it: the fault is alerted within 3 surfacings of its onset, sized within
// 20 % with an interval that covers it, and nothing is alerted before it.
// And the heading fit on surfacings launched anywhere (HealthHeadingFit).
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "glider/health/health.hpp"
#include "glider/health/output.hpp"
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

namespace {

const health::EffectValue& value_of(const health::SegmentMeasurement& m, health::HealthEffect e) {
  return m.effects[static_cast<std::size_t>(e)];
}

}  // namespace

// Health's heading fit (fin effectiveness, roll offset) reads the SIL's
// nominal fin whatever heading the glider starts a surfacing on, and does
// not depend on the vertical plane's Reynolds prior (docs/health.md, "Fin
// effectiveness on any launch heading", "The heading fit flies diagnose's
// heading vehicle").
TEST_GROUP(HealthHeadingFit){};

// Launched heading 0, 90 and 270 deg (the box's first leg is north: no
// long first turn, as the default launch of 180 deg +- 10 flies): the fin
// is measured on every sample, so the box's turns count whichever yos they
// fall in. The fit on alternate yos read the first 0.622 [0.463, 0.781]
// for the nominal 1, its turns all on the held-out yos.
TEST(HealthHeadingFit, ReadsTheNominalFinOnAnyLaunchHeading) {
  const std::string dir = fresh_dir("heading_any_launch");
  int k = 0;
  for (const int heading_deg : {0, 90, 270}) {
    // The launch heading is seed % 361 deg with a spread of 180 (sil_deployment.hpp).
    const std::uint64_t seed = 2 * 361 + heading_deg;
    const std::string error = health_sil::fly_surfacing(dir + "/sbd", {}, k++, kHoursApart, seed, {}, 180);
    CHECK_TEXT(error.empty(), error.c_str());
  }
  const health::HealthRun run = health::update_health(health_sil::health_options(dir, kHoursApart));
  int read = 0;
  for (const health::SegmentMeasurement& m : run.segments) {
    const health::EffectValue& fin = value_of(m, health::HealthEffect::kFinEffectiveness);
    if (!fin.judged()) continue;
    ++read;
    char text[200];
    std::snprintf(text, sizeof text, "%s: fin effectiveness %.4f [%.4f, %.4f] (truth 1)", m.name.c_str(), fin.value,
                  fin.low, fin.high);
    UT_PRINT(text);
    CHECK_TEXT(std::abs(fin.value - 1.0) <= 0.05, text);
    CHECK_TEXT(fin.low <= 1.0 && 1.0 <= fin.high, text);
  }
  CHECK_EQUAL(3, read);
  CHECK_EQUAL(0u, run.assessment.alerts.size());
}

// The vertical plane flies the skin friction's Reynolds prior (exponent 0.1)
// where the vehicle file is silent on it; the heading plane flies the file's
// vehicle with the vertical findings applied (heading_vehicle), so its fin
// and roll read the same either way. Flying diagnosed_nominal's prior there
// read the fin 0.0063-0.0068 lower and the roll offsets ~10 % larger on the
// SIL's .sbd (bench_health seed 546091495's first deployment).
TEST(HealthHeadingFit, FinAndRollDoNotDependOnTheReynoldsPrior) {
  const std::string dir = fresh_dir("heading_reynolds_prior");
  const std::string error = health_sil::fly_surfacing(dir + "/sbd", {}, 0, kHoursApart, 610);
  CHECK_TEXT(error.empty(), error.c_str());
  health::HealthOptions stated = health_sil::health_options(dir, kHoursApart);
  health::HealthOptions silent = stated;
  silent.vehicle.hydro.cd0_reynolds_exponent_stated = false;
  silent.state_path = dir + "/state_silent.json";
  const health::HealthRun a = health::update_health(stated);
  const health::HealthRun b = health::update_health(silent);
  CHECK_EQUAL(a.segments.size(), b.segments.size());
  int compared = 0;
  for (std::size_t s = 0; s < a.segments.size(); ++s) {
    const health::EffectValue& fin_a = value_of(a.segments[s], health::HealthEffect::kFinEffectiveness);
    const health::EffectValue& fin_b = value_of(b.segments[s], health::HealthEffect::kFinEffectiveness);
    const health::EffectValue& roll_a = value_of(a.segments[s], health::HealthEffect::kRollOffset);
    const health::EffectValue& roll_b = value_of(b.segments[s], health::HealthEffect::kRollOffset);
    if (!fin_a.judged()) continue;
    ++compared;
    char text[200];
    std::snprintf(text, sizeof text, "fin %.5f stated, %.5f silent; roll %.5f, %.5f deg", fin_a.value, fin_b.value,
                  roll_a.value, roll_b.value);
    UT_PRINT(text);
    CHECK_TEXT(std::abs(fin_a.value - fin_b.value) <= 0.002, text);
    CHECK_TEXT(std::abs(roll_a.value - roll_b.value) <= 0.05 * std::abs(roll_a.value) + 2e-4, text);
  }
  CHECK_EQUAL(1, compared);
}

// A segment that does not turn tells nothing of the fin: its fin makes only
// the autopilot's small corrections, which the closed loop reads weak
// (0.57-0.83 for 1 on straight SIL transects, spread 0.5-1.3 deg; the box's
// turns 4.7-5.2 deg). Such a segment's fin is "too thin to judge" and stays
// out of the fin's level, step and alert; a turning one is judged as before
// (docs/health.md, "The fin is judged only on segments that turn").
TEST_GROUP(HealthFinTurns){};

TEST(HealthFinTurns, AStraightTransectsFinIsNotJudged) {
  const std::string dir = fresh_dir("fin_turns");
  std::string error = health_sil::fly_transect(dir + "/sbd", {}, 0, kHoursApart, 901, 0.0);
  CHECK_TEXT(error.empty(), error.c_str());
  error = health_sil::fly_surfacing(dir + "/sbd", {}, 1, kHoursApart, 902);
  CHECK_TEXT(error.empty(), error.c_str());
  const health::HealthRun run = health::update_health(health_sil::health_options(dir, kHoursApart));
  int straight = 0, turning = 0;
  for (const health::SegmentMeasurement& m : run.segments) {
    if (!m.judged) continue;
    const health::EffectValue& fin = value_of(m, health::HealthEffect::kFinEffectiveness);
    char text[400];
    std::snprintf(text, sizeof text, "%s: fin spread %.2f deg, fin %.4f [%.4f, %.4f] %s", m.name.c_str(),
                  m.fin_spread_deg, fin.value, fin.low, fin.high, fin.why.c_str());
    UT_PRINT(text);
    if (m.name.find("-000-00-") != std::string::npos) {
      ++straight;
      CHECK_TEXT(!fin.judged(), text);
      CHECK_TEXT(fin.why.find("too thin to judge") != std::string::npos, text);
      CHECK_TEXT(m.fin_spread_deg < health::kMinFinSpreadDeg, text);
    } else {
      ++turning;
      CHECK_TEXT(fin.judged(), text);
      CHECK_TEXT(std::abs(fin.value - 1.0) <= 0.05, text);
    }
  }
  CHECK(straight >= 1);  // the transect's files (one or two segments)
  CHECK_EQUAL(1, turning);
  // The pilot reads why, in the text and in the JSON's segment.
  CHECK(health::health_text(run).find("fin_effectiveness not judged on") != std::string::npos);
  const std::string json = health::health_json(run);
  const std::size_t not_judged = json.find("\"not_judged\"");
  CHECK(not_judged != std::string::npos);
  CHECK(json.find("too thin to judge: the fin moved", not_judged) != std::string::npos);
}

// The fin in disturbed water: a random yaw (waves, turbulence) makes the
// autopilot move the fin without turning the glider, which the closed loop
// reads weak (0.28-0.45 for 1 on straight SIL transects whose fin moved 3-8
// deg, past the fin spread's 2.5 deg). Such a segment's fin is not judged:
// its heading did not turn (docs/health.md, "The fin in disturbed water").
TEST_GROUP(HealthFinDisturbed){};

// A straight transect and the box, both in the comet logs' strongest water
// (random yaw 0.8 deg/s over 4 s, compass noise 1.9 deg): the transect's fin
// moves past the fin spread's threshold but its heading does not turn, so
// its fin is not judged; the box's is.
TEST(HealthFinDisturbed, AFinChasingARandomYawIsNotJudged) {
  const std::string dir = fresh_dir("fin_disturbed");
  health_sil::FaultPlan water;
  water.disturbance.yaw_deg_s = 0.8;
  water.disturbance.compass_noise_deg = 1.9;
  std::string error = health_sil::fly_transect(dir + "/sbd", water, 0, kHoursApart, 911, 0.0);
  CHECK_TEXT(error.empty(), error.c_str());
  error = health_sil::fly_surfacing(dir + "/sbd", water, 1, kHoursApart, 912, {}, 180);
  CHECK_TEXT(error.empty(), error.c_str());
  const health::HealthRun run = health::update_health(health_sil::health_options(dir, kHoursApart));
  int straight = 0, turning = 0;
  for (const health::SegmentMeasurement& m : run.segments) {
    if (!m.judged) continue;
    const health::EffectValue& fin = m.effects[static_cast<std::size_t>(health::HealthEffect::kFinEffectiveness)];
    char text[500];
    std::snprintf(text, sizeof text, "%s: fin spread %.2f deg, heading spread %.2f deg, fin %.4f [%.4f, %.4f] %s",
                  m.name.c_str(), m.fin_spread_deg, m.heading_spread_deg, fin.value, fin.low, fin.high,
                  fin.why.c_str());
    UT_PRINT(text);
    if (m.name.find("-000-00-") != std::string::npos) {
      ++straight;
      CHECK_TEXT(m.fin_spread_deg >= health::kMinFinSpreadDeg, text);  // the fin's spread alone would judge it
      CHECK_TEXT(m.heading_spread_deg < health::kMinHeadingSpreadDeg, text);
      CHECK_TEXT(!fin.judged(), text);
      CHECK_TEXT(fin.why.find("the heading turned") != std::string::npos, text);
    } else {
      ++turning;
      CHECK_TEXT(m.heading_spread_deg >= health::kMinHeadingSpreadDeg, text);
      CHECK_TEXT(fin.judged(), text);
    }
  }
  CHECK(straight >= 1);
  CHECK_EQUAL(1, turning);
}
