// SPDX-License-Identifier: Apache-2.0
// The heading plane: hide an effect in the servo, the vehicle or the
// autopilot of a SIL flight, hand only the (thinned) CSV to the diagnosis,
// and require it to name the effect, hold the truth inside its 95 % interval
// and gain on the held-out glides. Magnitudes come from a seeded generator.
#include <CppUTest/TestHarness.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "glider/units.hpp"
#include "hidden_heading_flight.hpp"

using namespace glider;
using diagnose::HeadingEffect;
using hidden::comet;
using hidden::configured_slocum_law;
using hidden::finding;
using hidden::fly_heading_and_diagnose;
using hidden::HeadingOutcome;
using hidden::uniform;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The named effect: found, truth inside its interval, printed for the record.
const diagnose::HeadingFinding& require_found(const HeadingOutcome& o, HeadingEffect effect, double truth) {
  const diagnose::HeadingFinding* f = finding(o.diagnosis, effect);
  char text[200];
  std::snprintf(text, sizeof text, "%s: hidden %.6g; found %.6g (CI %.6g .. %.6g), link gain %.3f",
                diagnose::info(effect).id, truth, f ? f->value : kNaN, f ? f->ci95_low : kNaN, f ? f->ci95_high : kNaN,
                f ? f->gain : kNaN);
  UT_PRINT(text);
  CHECK_TEXT(f != nullptr, text);
  // A replay that is exact (the servo and the law in SIL) fits with zero
  // residual and a zero-width interval: rounding slack of 1e-6 of the scale.
  const double slack = 1e-6 * diagnose::info(effect).scale;
  CHECK_TEXT(f->ci95_low - slack <= truth && truth <= f->ci95_high + slack, text);
  return *f;
}

}  // namespace

TEST_GROUP(DiagnoseHiddenHeadingEffects) { std::mt19937_64 rng{20261125}; };

TEST(DiagnoseHiddenHeadingEffects, CleanLogNamesNone) {
  const HeadingOutcome o = fly_heading_and_diagnose(comet(), configured_slocum_law(), "none");
  STRCMP_EQUAL("none", o.diagnosis.cause.c_str());
  LONGS_EQUAL(0, o.diagnosis.servo.findings.size());
  LONGS_EQUAL(0, o.diagnosis.autopilot.findings.size());
  // In still water the shear profile explains nothing on held-out glides.
  const diagnose::ShearProfile& shear = o.diagnosis.current_shear;
  CHECK(shear.heldout_rms_after > 0.9 * shear.heldout_rms_before);
}

TEST(DiagnoseHiddenHeadingEffects, FinDelay) {
  // Whole cycles: the SIL applies a queued fin command at its first
  // integration step at or after it is due, i.e. on the 4 s cycle.
  const double delay_s = 4.0 * static_cast<double>(1 + rng() % 3);
  model::VehicleParams flown = comet();
  flown.heading.fin_delay_s = delay_s;
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "fin_delay");
  STRCMP_EQUAL("fin_delay", o.diagnosis.cause.c_str());
  const auto& f = require_found(o, HeadingEffect::kFinDelay, delay_s);
  DOUBLES_EQUAL(delay_s, f.value, 1.0);
  CHECK(o.diagnosis.servo.gain > 0.3);
  DOUBLES_EQUAL(delay_s, apply(comet(), o.diagnosis).heading.fin_delay_s, 1.5);
}

// The comet logs' servos do not follow a command within 0.02-0.045 rad of
// where the fin is (glider-diagnose: fin_deadband).
TEST(DiagnoseHiddenHeadingEffects, FinDeadband) {
  model::VehicleParams flown = comet();
  flown.heading.fin_deadband_rad = uniform(rng, 0.02, 0.06);
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "fin_deadband");
  const auto& f = require_found(o, HeadingEffect::kFinDeadband, flown.heading.fin_deadband_rad);
  DOUBLES_EQUAL(flown.heading.fin_deadband_rad, f.value, 0.005);
  CHECK(o.diagnosis.servo.gain > 0.3);
  DOUBLES_EQUAL(flown.heading.fin_deadband_rad, apply(comet(), o.diagnosis).heading.fin_deadband_rad, 0.005);
}

// A current that turns across the heading with depth (the comet logs' yaw
// no link explained, docs/diagnose/heading.md): the glider crossing it turns
// one way diving and the other climbing. Here a jet between 10 and 35 m
// (shear +S above its core, -S below). The profile must come out with the
// jet's shape (its correlation with the hidden one by bin), the same from
// dives and climbs, and cut the held-out yaw rate. Known weakness: the
// vehicle link is fitted first and takes part of the shear's turns as a
// longer yaw lag (seed 20261125: yaw_time_constant 11.3 s for a nominal 2 s),
// so the profile is smaller than the truth (0.0040-0.0070 for S 0.0082) and
// not every bin's interval holds it: the sizes are not asserted.
TEST(DiagnoseHiddenHeadingEffects, CurrentShearAcrossTheHeading) {
  const double shear = uniform(rng, 0.008, 0.015) * (rng() % 2 ? 1.0 : -1.0);  // 1/s, east across a north heading
  std::vector<model::ProfileNode> nodes(5);
  for (const auto& [k, depth, current] :
       {std::tuple{0, 0.0, 0.0}, {1, 10.0, 0.0}, {2, 20.0, 10.0 * shear}, {3, 25.0, 10.0 * shear}, {4, 35.0, 0.0}}) {
    nodes[static_cast<std::size_t>(k)].depth_m = depth;
    nodes[static_cast<std::size_t>(k)].water.current_east_m_s = current;
  }
  model::Environment water;
  water.water = model::WaterColumn(nodes, {});
  const HeadingOutcome o = fly_heading_and_diagnose(comet(), configured_slocum_law(), "current_shear", 0.0, water);
  const diagnose::ShearProfile& p = o.diagnosis.current_shear;
  double found_truth = 0.0, found_found = 0.0, truth_truth = 0.0;
  for (const diagnose::ShearBin& b : p.bins) {
    if (!b.fitted) continue;
    const double truth = b.to_m <= 10.0 || (b.from_m >= 20.0 && b.to_m <= 25.0) || b.from_m >= 35.0 ? 0.0
                         : b.to_m <= 20.0                                                           ? shear
                                                                                                    : -shear;
    char text[160];
    std::snprintf(text, sizeof text, "%.0f-%.0f m: hidden %+.4f; found %+.4f [%+.4f, %+.4f] over %zu glides", b.from_m,
                  b.to_m, truth, b.shear_per_s, b.ci95_low, b.ci95_high, b.runs);
    UT_PRINT(text);
    found_truth += b.shear_per_s * truth;
    found_found += b.shear_per_s * b.shear_per_s;
    truth_truth += truth * truth;
  }
  const double shape = found_truth / std::sqrt(found_found * truth_truth);
  char text[200];
  std::snprintf(text, sizeof text, "shape correlation %.3f; held-out yaw rate %.4f -> %.4f rad/s; dives vs climbs %.3f",
                shape, p.heldout_rms_before, p.heldout_rms_after, p.dive_climb_correlation);
  UT_PRINT(text);
  CHECK_TEXT(shape > 0.9, text);
  // Seed 20261125: shape 0.939, held-out 0.0025 -> 0.0015 rad/s, dives vs
  // climbs 0.79; the clean log's profile: 0.046 -> 0.044 deg/s, -0.45.
  CHECK_TEXT(p.heldout_rms_after < 0.7 * p.heldout_rms_before, text);
  CHECK_TEXT(p.dive_climb_correlation > 0.7, text);
}

// A compass that reports the heading late (its filtering): the yaw answers
// the fin that much later in the log, after the fin reading (yaw_delay);
// the autopilot reads the same late heading, so its own lag is unchanged.
// Whole cycles, as the SIL's compass is read once per 4 s cycle.
TEST(DiagnoseHiddenHeadingEffects, CompassLagIsAYawDelay) {
  const double delay_s = 4.0 * static_cast<double>(1 + rng() % 2);
  const HeadingOutcome o =
      fly_heading_and_diagnose(comet(), configured_slocum_law(), "yaw_delay", 0.0, model::Environment{}, delay_s);
  const auto& f = require_found(o, HeadingEffect::kYawDelay, delay_s);
  DOUBLES_EQUAL(delay_s, f.value, 1.0);
  CHECK(o.diagnosis.yaw.gain > 0.2);
  CHECK(finding(o.diagnosis, HeadingEffect::kAutopilotDelay) == nullptr);
}

TEST(DiagnoseHiddenHeadingEffects, FinEffectiveness) {
  const double factor = rng() % 2 ? uniform(rng, 0.5, 0.75) : uniform(rng, 1.35, 1.8);
  model::VehicleParams flown = comet();
  flown.heading.fin_yaw_gain_per_m *= factor;
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "fin_effectiveness");
  const auto& f = require_found(o, HeadingEffect::kFinEffectiveness, factor);
  CHECK(std::abs(f.value - factor) < 0.1 * factor);
  CHECK(o.diagnosis.yaw.gain > 0.2);
}

TEST(DiagnoseHiddenHeadingEffects, RollOffsetTheLogDoesNotShow) {
  const double delta = deg_to_rad(uniform(rng, 3.0, 6.0)) * (rng() % 2 ? 1.0 : -1.0);
  model::VehicleParams flown = comet();
  flown.heading.roll_offset_rad += delta;
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "roll_offset", delta);
  const auto& f = require_found(o, HeadingEffect::kRollOffset, delta);
  DOUBLES_EQUAL(delta, f.value, deg_to_rad(1.0));
  CHECK(o.diagnosis.yaw.gain > 0.2);
}

TEST(DiagnoseHiddenHeadingEffects, IntegralThatNeverActs) {
  fw::HeadingControlConfig flown_law = configured_slocum_law();
  flown_law.igain = 0.0;  // the header still says 0.02
  const HeadingOutcome o = fly_heading_and_diagnose(comet(), flown_law, "integral_off");
  const auto& f = require_found(o, HeadingEffect::kAutopilotIntegral, 0.0);
  CHECK(f.ci95_high < configured_slocum_law().igain);
  CHECK(o.diagnosis.autopilot.gain > 0.3);
}

TEST(DiagnoseHiddenHeadingEffects, YawTimeConstant) {
  const double tau_s = uniform(rng, 6.0, 12.0);
  model::VehicleParams flown = comet();
  flown.heading.yaw_time_constant_s = tau_s;
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "yaw_time_constant");
  require_found(o, HeadingEffect::kYawTimeConstant, tau_s);
  CHECK(o.diagnosis.yaw.gain > 0.2);
}

// What the comet logs show: a lower gain and no integral than the header's.
// (A lower gain WITH the header's integral winds up in the SIL's first turn
// and circles with the fin hard over: no gain can be seen in such a log.)
TEST(DiagnoseHiddenHeadingEffects, ProportionalGainNotTheConfiguredOne) {
  fw::HeadingControlConfig flown_law = configured_slocum_law();
  flown_law.gain = uniform(rng, 0.4, 0.9);  // the header still says 1.5 and 0.02
  flown_law.igain = 0.0;
  const HeadingOutcome o = fly_heading_and_diagnose(comet(), flown_law, "autopilot_gain");
  require_found(o, HeadingEffect::kAutopilotGain, flown_law.gain);
  require_found(o, HeadingEffect::kAutopilotIntegral, 0.0);
  CHECK(o.diagnosis.autopilot.gain > 0.3);
}

// The comet logs hold the fin while the error is small: a heading deadband.
TEST(DiagnoseHiddenHeadingEffects, HeadingDeadband) {
  fw::HeadingControlConfig flown_law = configured_slocum_law();
  flown_law.heading_deadband_rad = uniform(rng, 0.05, 0.12);  // the header states none
  const HeadingOutcome o = fly_heading_and_diagnose(comet(), flown_law, "autopilot_deadband");
  require_found(o, HeadingEffect::kAutopilotDeadband, flown_law.heading_deadband_rad);
  CHECK(o.diagnosis.autopilot.gain > 0.3);
}

// A random yaw no link explains (heading.yaw_disturbance_*) shows as the yaw
// rate left unexplained. Known weakness: a disturbance correlated over 10 s
// is partly taken by yaw_time_constant (seed 20261125: 10.1 s [5.1, 15.2]
// for a nominal 2 s, 13 % held-out gain), so the test does not ask for none.
TEST(DiagnoseHiddenHeadingEffects, RandomYawIsLeftUnexplained) {
  model::VehicleParams flown = comet();
  flown.heading.yaw_disturbance_rad_s = uniform(rng, 0.004, 0.008);
  flown.heading.yaw_disturbance_correlation_s = 10.0;
  const HeadingOutcome clean = fly_heading_and_diagnose(comet(), configured_slocum_law(), "yaw_clean");
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "yaw_disturbance");
  CHECK(o.diagnosis.unexplained_yaw_rate_rad_s > 3.0 * clean.diagnosis.unexplained_yaw_rate_rad_s);
  CHECK(o.diagnosis.unexplained_yaw_rate_rad_s < flown.heading.yaw_disturbance_rad_s);  // the estimator smooths it
}

// The loop closed on the log (heading_closed_loop.hpp) with the diagnosis's
// values, on a SIL flight whose plant is the model's: the glides' mean
// heading error and fin travel must come out as the log's, far closer than
// the configured law's. A lower gain, no integral and a heading deadband,
// as the comet logs fly.
TEST(DiagnoseHiddenHeadingEffects, ClosedLoopReproducesTheFlight) {
  fw::HeadingControlConfig flown_law = configured_slocum_law();
  flown_law.gain = uniform(rng, 0.4, 0.9);
  flown_law.igain = 0.0;
  flown_law.heading_deadband_rad = uniform(rng, 0.05, 0.12);
  const HeadingOutcome o = fly_heading_and_diagnose(comet(), flown_law, "closed_loop");
  const diagnose::ClosedLoopCheck& c = o.diagnosis.closed_loop;
  char text[400];
  std::snprintf(text, sizeof text,
                "gain %.3f, deadband %.3f rad: closed loop over %zu held-out glides, model - log: configured %.2f deg "
                "%.2f rad/h (score %.2f), identified %.2f deg %.2f rad/h (score %.2f); log scatter %.2f deg %.2f rad/h",
                flown_law.gain, flown_law.heading_deadband_rad, c.heldout_glides,
                rad_to_deg(c.configured.error_rms_rad), 3600.0 * c.configured.travel_rms_rad_s, c.configured.score,
                rad_to_deg(c.open_loop_set.error_rms_rad), 3600.0 * c.open_loop_set.travel_rms_rad_s,
                c.open_loop_set.score, rad_to_deg(c.error_scatter_rad), 3600.0 * c.travel_scatter_rad_s);
  UT_PRINT(text);
  CHECK(c.heldout_glides >= 4);
  CHECK(c.open_loop_set.score < 0.5 * c.configured.score);
  CHECK(c.open_loop_set.error_rms_rad < deg_to_rad(1.0));
}

// The fin's authority in a closed loop (docs/science.md): a random yaw the
// glider's own autopilot answers with its fin makes the logged fin track the
// water's yaw, and the yaw rate of the logged fin against the measured one
// reads the fin weaker than it is. The SIL flies the model's own yaw (no
// model-form error) with the vehicle file's fin and a random yaw correlated
// over 30 s. The rate error alone (yaw_noise_model off: the method before)
// names a weaker fin, 1 outside its interval - the cause; the diagnosis,
// which measures the fin it chose on the heading's innovations with the
// random yaw and the compass noise modelled, must not name it, or must hold
// 1 in its interval.
TEST(DiagnoseHiddenHeadingEffects, RandomYawDoesNotWeakenTheFin) {
  model::VehicleParams flown = comet();
  flown.heading.yaw_disturbance_rad_s = uniform(rng, 0.005, 0.007);
  flown.heading.yaw_disturbance_correlation_s = 30.0;
  const HeadingOutcome o = fly_heading_and_diagnose(flown, configured_slocum_law(), "fin_random_yaw");
  const flightlog::FlightLog log = flightlog::read_flight_log(o.log_path);
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& m : log.vehicle_metadata()) entries.emplace_back(m.key, m.value);
  const model::VehicleParams from_log = model::vehicle_from_metadata(entries, o.log_path);
  diagnose::HeadingDiagnoseOptions before;
  before.yaw_noise_model = false;
  const diagnose::HeadingDiagnosis biased = diagnose::diagnose_heading(from_log, log, before);
  const diagnose::HeadingFinding* b = finding(biased, HeadingEffect::kFinEffectiveness);
  const diagnose::HeadingFinding* f = finding(o.diagnosis, HeadingEffect::kFinEffectiveness);
  const auto& refuted = o.diagnosis.yaw.dropped;
  const auto fin_refuted = std::find_if(refuted.begin(), refuted.end(), [](const diagnose::HeadingFinding& x) {
    return x.effect == HeadingEffect::kFinEffectiveness;
  });
  const diagnose::HeadingFinding* r = fin_refuted == refuted.end() ? nullptr : &*fin_refuted;
  char text[520];
  std::snprintf(text, sizeof text,
                "random yaw %.4f rad/s over 30 s, fin x1: rate error alone %s %.3f [%.3f, %.3f]; diagnosis %s %.3f "
                "[%.3f, %.3f]; on the innovations %.3f [%.3f, %.3f]; noise fitted: compass %.4f rad, random yaw %.4f "
                "rad/s over %.0f s",
                flown.heading.yaw_disturbance_rad_s, b ? "names the fin" : "does not name the fin", b ? b->value : kNaN,
                b ? b->ci95_low : kNaN, b ? b->ci95_high : kNaN, f ? "names the fin" : "does not name the fin",
                f ? f->value : kNaN, f ? f->ci95_low : kNaN, f ? f->ci95_high : kNaN, r ? r->value : kNaN,
                r ? r->ci95_low : kNaN, r ? r->ci95_high : kNaN, o.diagnosis.yaw_noise.heading_rad,
                o.diagnosis.yaw_noise.disturbance_rad_s, o.diagnosis.yaw_noise.correlation_s);
  UT_PRINT(text);
  CHECK_TEXT(b != nullptr && b->ci95_high < 1.0, text);  // the cause: the method before names a weaker fin
  CHECK_TEXT(f == nullptr || (f->ci95_low <= 1.0 && 1.0 <= f->ci95_high), text);
}
