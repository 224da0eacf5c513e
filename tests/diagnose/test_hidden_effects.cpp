// SPDX-License-Identifier: Apache-2.0
// Hide an effect in SIL-made data, hand only the CSV to the diagnosis, and
// require it to name the effect, recover its size and gain on held-out yos.
// Magnitudes are drawn from realistic ranges by a seeded generator.
#include <CppUTest/TestHarness.h>

#include <cstdio>

#include <cmath>
#include <random>
#include <string>

#include "glider/units.hpp"
#include "hidden_effect_flight.hpp"

using namespace glider;
using hidden::fly_and_diagnose;
using hidden::Outcome;
using hidden::uniform;
using hidden::we01;

TEST_GROUP(DiagnoseHiddenEffects) {
  std::mt19937_64 rng{20261122};
  // Every log thinned like a real Slocum log (rows 2-5 s apart, sci_* gaps):
  // against 1 Hz logs the recovered values moved by < 10 % of each tolerance.
  const sil::LogGaps gaps = hidden::real_log_gaps();
};

TEST(DiagnoseHiddenEffects, CleanDataNamesNone) {
  const Outcome o = fly_and_diagnose(we01(), model::still_water(1025.0), "none", 80.0, gaps);
  STRCMP_EQUAL("none", o.diagnosis.cause.c_str());
  LONGS_EQUAL(0, o.diagnosis.findings.size());
  CHECK(o.diagnosis.baseline.all.depth_rate_m_s < 0.02);
}

TEST(DiagnoseHiddenEffects, BuoyancyOffset) {
  const double grams = uniform(rng, 25.0, 60.0) * (rng() % 2 ? 1.0 : -1.0);
  model::VehicleParams flown = we01();
  flown.buoyancy_offset_kg = grams * 1e-3;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "buoyancy_offset", 80.0, gaps);
  char text[160];
  std::snprintf(text, sizeof text, "hidden %.2f g; found %.2f g (CI %.2f .. %.2f)", grams,
                o.diagnosis.findings.empty() ? 0.0 : o.diagnosis.findings.front().value,
                o.diagnosis.findings.empty() ? 0.0 : o.diagnosis.findings.front().ci95_low,
                o.diagnosis.findings.empty() ? 0.0 : o.diagnosis.findings.front().ci95_high);
  UT_PRINT(text);
  STRCMP_EQUAL("buoyancy_offset", o.diagnosis.cause.c_str());
  DOUBLES_EQUAL(grams, o.diagnosis.findings.front().value, 5.0);  // within 5 g
  CHECK(o.diagnosis.findings.front().ci95_low < grams && grams < o.diagnosis.findings.front().ci95_high);
  CHECK(o.diagnosis.gain > 0.5);
}

TEST(DiagnoseHiddenEffects, DragChange) {
  const double ratio = uniform(rng, 1.15, 1.5);
  model::VehicleParams flown = we01();
  flown.hydro.cd0 *= ratio;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "drag_change", 80.0, gaps);
  STRCMP_EQUAL("drag_change", o.diagnosis.cause.c_str());
  DOUBLES_EQUAL(ratio, o.diagnosis.findings.front().value, 0.03);
  CHECK(o.diagnosis.gain > 0.5);
}

TEST(DiagnoseHiddenEffects, VerticalWaterVelocityInALayer) {
  // Downwelling (or upwelling) in a layer, as an internal wave or a front
  // makes: 2-4 cm/s between 25 and 45 m, still water above and below.
  const double w = uniform(rng, 0.02, 0.04) * (rng() % 2 ? 1.0 : -1.0);
  const model::Environment water = hidden::vertical_velocity_layer(w);
  const Outcome o = fly_and_diagnose(we01(), water, "vertical_water_velocity", 80.0, gaps);
  STRCMP_EQUAL("vertical_water_velocity", o.diagnosis.cause.c_str());
  // The value is the mean over the log: compare with the simulator's truth
  // over the glides' samples (sim_ columns check the analysis, never feed it).
  const double truth = hidden::glide_mean_vertical_velocity(flightlog::read_flight_log(o.log_path));
  DOUBLES_EQUAL(truth, o.diagnosis.findings.front().value, 0.003);
  CHECK(o.diagnosis.gain > 0.5);
}

TEST(DiagnoseHiddenEffects, HullCompressibility) {
  // A hull a few 1e-10 /Pa softer than nominal gains ~10-30 g over 180 m:
  // dives speed up and climbs slow down with depth.
  const double eps = uniform(rng, 1.5e-10, 3e-10);
  model::VehicleParams flown = we01();
  flown.hull_compressibility_per_pa = eps;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "hull_compressibility", 180.0, gaps);
  STRCMP_EQUAL("hull_compressibility", o.diagnosis.cause.c_str());
  // Within 10 % and inside its own 95 % interval. (The steady model read this
  // flight 20 % high - 3.54e-10 for 2.90e-10: its glides at the measured
  // pitch ignore the pitch and speed transients that the dynamic model flies.)
  const diagnose::Finding& f = o.diagnosis.findings.front();
  DOUBLES_EQUAL(eps, f.value, 0.1 * eps);
  CHECK(f.ci95_low < eps && eps < f.ci95_high);
  CHECK(o.diagnosis.gain > 0.5);
}

TEST(DiagnoseHiddenEffects, TwoEffectsAtOnce) {
  const double grams = -uniform(rng, 30.0, 60.0);
  const double ratio = uniform(rng, 1.2, 1.4);
  model::VehicleParams flown = we01();
  flown.buoyancy_offset_kg = grams * 1e-3;
  flown.hydro.cd0 *= ratio;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "two_effects", 80.0, gaps);
  LONGS_EQUAL(2, o.diagnosis.findings.size());
  bool found_offset = false, found_drag = false;
  for (const auto& f : o.diagnosis.findings) {
    if (f.effect == diagnose::Effect::kBuoyancyOffset) {
      found_offset = true;
      DOUBLES_EQUAL(grams, f.value, 6.0);
    }
    if (f.effect == diagnose::Effect::kDragChange) {
      found_drag = true;
      DOUBLES_EQUAL(ratio, f.value, 0.04);
    }
  }
  CHECK_TRUE(found_offset && found_drag);
  CHECK(o.diagnosis.gain > 0.6);
}

TEST(DiagnoseHiddenEffects, OffsetAndCompressibilityAreNotAWaterProfile) {
  // A buoyancy offset and a softer hull: each alone explains less than a
  // vertical-velocity depth profile (which mimics any buoyancy changing with
  // depth), the two together more. The greedy forward step took the profile;
  // the selection without it must now win unless the profile earns its place.
  // The values of bench_diagnose_coverage's draw 20261126, read as a profile
  // alone before (the test group's first draw, -57.6 g and 1.93e-10 /Pa, was
  // named right either way).
  const double grams = -37.17, eps = 2.615e-10;
  model::VehicleParams flown = we01();
  flown.buoyancy_offset_kg = grams * 1e-3;
  flown.hull_compressibility_per_pa = eps;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "offset_compressibility", 180.0, gaps);
  char line[128];
  std::snprintf(line, sizeof line, "hidden %.4g g, %.4g /Pa:", grams, eps);
  std::string text = line;
  for (const auto& f : o.diagnosis.findings) {
    std::snprintf(line, sizeof line, " %s %.4g (CI %.4g .. %.4g)", diagnose::info(f.effect).id, f.value, f.ci95_low,
                  f.ci95_high);
    text += line;
  }
  UT_PRINT(text.c_str());
  LONGS_EQUAL(2, o.diagnosis.findings.size());
  for (const auto& f : o.diagnosis.findings) {
    const double truth = f.effect == diagnose::Effect::kBuoyancyOffset ? grams : eps;
    CHECK(f.effect == diagnose::Effect::kBuoyancyOffset || f.effect == diagnose::Effect::kHullCompressibility);
    CHECK(f.ci95_low < truth && truth < f.ci95_high);
  }
}

TEST(DiagnoseHiddenEffects, PitchTrimOffset) {
  // A CG error equivalent to the battery sitting 0.05-0.15 in further forward
  // than its reading (a mis-placed trim weight): the pitch servo holds the
  // commanded pitch with the battery that much further aft on every glide.
  const double inches = uniform(rng, 0.05, 0.15) * (rng() % 2 ? 1.0 : -1.0);
  model::VehicleParams flown = we01();
  flown.battery.x_at_zero_m += in_to_m(inches);
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "pitch_trim_offset", 80.0, gaps);
  STRCMP_EQUAL("pitch_trim_offset", o.diagnosis.cause.c_str());
  DOUBLES_EQUAL(inches, o.diagnosis.findings.front().value, 0.02);
}

TEST(DiagnoseHiddenEffects, PumpLag) {
  // The displaced volume trails the pump's reported position by a first-order
  // lag (paper 003's ballast-to-buoyancy dynamics): only the turns show it,
  // where the glider turns later than a model fed the logged ballast.
  const double lag_s = uniform(rng, 5.0, 15.0);
  model::VehicleParams flown = we01();
  flown.ballast.lag_s = lag_s;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "pump_lag");
  STRCMP_EQUAL("pump_lag", o.diagnosis.cause.c_str());
  const diagnose::Finding& f = o.diagnosis.findings.front();
  DOUBLES_EQUAL(lag_s, f.value, 0.15 * lag_s);
  CHECK(f.ci95_low < lag_s && lag_s < f.ci95_high);
  CHECK(o.diagnosis.gain > 0.2);
  // The steady model, which does not fly turns, must not see it at all.
  diagnose::DiagnoseOptions steady;
  steady.model = diagnose::FlightModelKind::kSteady;
  const flightlog::FlightLog log = flightlog::read_flight_log(o.log_path);
  std::vector<std::pair<std::string, std::string>> entries;
  for (const auto& m : log.vehicle_metadata()) entries.emplace_back(m.key, m.value);
  const diagnose::Diagnosis d = diagnose::diagnose(model::vehicle_from_metadata(entries, o.log_path),
                                                   diagnose::prepare_observations(log), steady);
  for (const auto& finding : d.findings) CHECK(finding.effect != diagnose::Effect::kPumpLag);
}

TEST(DiagnoseHiddenEffects, PumpLagOnAThinnedLog) {
  // A row every 2-5 s: a 10-20 s pump stroke is 3-6 samples. Read as straight
  // lines between them, the stroke starts early and ends late, and the lag
  // comes out short (bench_diagnose_coverage: -0.1 s, coverage 52 %; here
  // 7.793 s read 7.695). Rebuilt as the pump flew it (pump_ramp.hpp): 7.821,
  // within 1 % and inside its 95 % interval. A short lag (5-8 s), where the
  // smear is the larger part of it.
  const double lag_s = uniform(rng, 5.0, 8.0);
  model::VehicleParams flown = we01();
  flown.ballast.lag_s = lag_s;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "pump_lag_thinned", 80.0, gaps);
  STRCMP_EQUAL("pump_lag", o.diagnosis.cause.c_str());
  LONGS_EQUAL(1, o.diagnosis.findings.size());
  const diagnose::Finding& f = o.diagnosis.findings.front();
  UT_PRINT(("hidden lag " + std::to_string(lag_s) + " s; read " + std::to_string(f.value) + " (CI " +
            std::to_string(f.ci95_low) + " .. " + std::to_string(f.ci95_high) + ")")
               .c_str());
  DOUBLES_EQUAL(lag_s, f.value, 0.01 * lag_s);
  CHECK(f.ci95_low < lag_s && lag_s < f.ci95_high);
}

TEST(DiagnoseHiddenEffects, LiftChange) {
  // The lift slope off the nominal (a fouled or damaged wing, another wing
  // set): the angle of attack, hence the speed along the measured pitch,
  // differs, which is what dead reckoning and turbulence science need. The
  // dynamic model sees it in the turns and transients, where the angle of
  // attack swings. On the thinned log, within 2.5 % and inside its 95 %
  // interval: a straight line between the 2-5 s samples of a pump stroke read
  // 1.347 as 1.395; the pump rebuilt as the actuator it
  // is (pump_ramp.hpp) reads 1.365 (CI 1.338 .. 1.391).
  const double ratio = rng() % 2 ? uniform(rng, 0.65, 0.85) : uniform(rng, 1.25, 1.5);
  model::VehicleParams flown = we01();
  flown.hydro.cl_alpha *= ratio;
  flown.hydro.cl_alpha_abs_alpha *= ratio;
  const Outcome o = fly_and_diagnose(flown, model::still_water(1025.0), "lift_change", 80.0, gaps);
  std::string text = "hidden ratio " + std::to_string(ratio) + "; cause " + o.diagnosis.cause + ":";
  for (const auto& f : o.diagnosis.findings) {
    text += std::string(" ") + diagnose::info(f.effect).id + " " + std::to_string(f.value) + " (CI " +
            std::to_string(f.ci95_low) + " .. " + std::to_string(f.ci95_high) + ")";
  }
  UT_PRINT(text.c_str());
  STRCMP_EQUAL("lift_change", o.diagnosis.cause.c_str());
  LONGS_EQUAL(1, o.diagnosis.findings.size());
  const diagnose::Finding& f = o.diagnosis.findings.front();
  DOUBLES_EQUAL(ratio, f.value, 0.025 * ratio);
  CHECK(f.ci95_low < ratio && ratio < f.ci95_high);
  CHECK(o.diagnosis.gain > 0.5);
}
