// SPDX-License-Identifier: Apache-2.0
// Truth flights: they complete, are the same for the same seed, write a log
// the project's reader takes (thinned like Slocum's), and each hidden effect
// does what it says.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "glider/flightlog/flight_log.hpp"
#include "glider/truth/effects.hpp"
#include "glider/truth/flight.hpp"
#include "glider/truth/log_writer.hpp"

using namespace glider::truth;

namespace {

FlightRequest request(std::uint64_t seed, Effects effects = {}) {
  FlightRequest r;
  r.vehicle_path = std::string(GLIDER_SOURCE_DIR) + "/boards/vehicles/slocum_shallow.toml";
  r.seed = seed;
  r.yos = 3;
  r.effects = std::move(effects);
  r.cycle_s = 4.0;
  r.dive_to_m = 50.0;
  return r;
}

double mean_glide_speed(const FlightResult& f) {
  double sum = 0.0;
  int n = 0;
  for (const Sample& s : f.samples) {
    if (s.true_depth_m > 15.0 && s.true_depth_m < 40.0) {
      sum += s.speed_m_s;
      ++n;
    }
  }
  return sum / n;
}

}  // namespace

TEST_GROUP(TruthFlight){};

TEST(TruthFlight, CompletesAndLogsLikeSlocum) {
  const FlightResult f = fly(request(3));
  const std::string path = (std::filesystem::temp_directory_path() / "truth_flight_test.csv").string();
  write_log(path, f, {"slocum_shallow.toml", 3});
  const glider::flightlog::FlightLog log = glider::flightlog::read_flight_log(path);
  std::filesystem::remove(path);
  CHECK(log.end().state == glider::flightlog::LogEnd::State::kComplete);
  // ~2 % of cycles dropped, whole.
  CHECK(log.rows() < f.samples.size());
  CHECK(log.rows() > f.samples.size() * 0.9);
  DOUBLES_EQUAL(1.0, log.fill_fraction("m_depth"), 1e-12);
  DOUBLES_EQUAL(1.0, log.fill_fraction("m_ballast_pumped"), 1e-12);
  // Commands only when they change: a handful of pump commands, 3 yos.
  CHECK(log.fill_fraction("c_ballast_pumped") < 0.05);
  CHECK(log.fill_fraction("sci_water_temp") > 0.85);
  double deepest = 0.0;
  for (double d : log.column("m_depth")) deepest = std::max(deepest, d);
  CHECK(deepest > 49.0 && deepest < 56.0);
  DOUBLES_EQUAL(3.0, log.column("x_yo_count").back(), 0.0);
  DOUBLES_EQUAL(0.0, log.column("m_depth_state").back(), 0.0);
  CHECK(log.metadata().size() >= 3);
}

TEST(TruthFlight, SameSeedSameLogOtherSeedOther) {
  const std::string a = log_text(fly(request(5)), {"v", 5});
  const std::string b = log_text(fly(request(5)), {"v", 5});
  const std::string c = log_text(fly(request(6)), {"v", 6});
  CHECK(a == b);
  CHECK(a != c);
}

TEST(TruthFlight, BothPitchControllersFly) {
  for (PitchControl control : {PitchControl::kPi, PitchControl::kBangBang}) {
    FlightRequest r = request(8);
    r.control = control;
    const FlightResult f = fly(r);
    // Settled pitch within 3 deg of its target mid-glide, on average.
    double error = 0.0;
    int n = 0;
    for (const Sample& s : f.samples) {
      if (s.true_depth_m > 20.0 && s.true_depth_m < 40.0 && std::isfinite(s.c_pitch_rad)) {
        error += std::abs(s.pitch_rad - s.c_pitch_rad);
        ++n;
      }
    }
    CHECK(n > 20);
    CHECK_TRUE(error / n < 0.05);
  }
}

TEST_GROUP(TruthEffects){};

TEST(TruthEffects, RefusesBadEffects) {
  CHECK_THROWS(std::invalid_argument, parse_effect("drag_change"));
  CHECK_THROWS(std::invalid_argument, parse_effect("no_such_effect=1"));
  CHECK_THROWS(std::invalid_argument, parse_effect("drag_change=nan"));
  CHECK_THROWS(std::invalid_argument, parse_effect("drag_change=1.2x"));
  CHECK_THROWS(std::invalid_argument, parse_effect("drag_change=9"));
  const auto ok = parse_effect("pump_lag=8");
  STRCMP_EQUAL("pump_lag", ok.first.c_str());
  DOUBLES_EQUAL(8.0, ok.second, 0.0);
}

// More drag, same buoyancy: slower by about the square root (the glide
// angle changes a little too).
TEST(TruthEffects, DragChangeSlowsTheGlide) {
  const double clean = mean_glide_speed(fly(request(9)));
  const double dragged = mean_glide_speed(fly(request(9, {{"drag_change", 1.4}})));
  DOUBLES_EQUAL(1.0 / std::sqrt(1.4), dragged / clean, 0.06);
}

// The vertical water velocity's truth is its mean over the glides: with
// the sign of the hidden layer's, and smaller (the layer is part of the column).
TEST(TruthEffects, VerticalVelocityTruthIsItsGlideMean) {
  const FlightResult f = fly(request(10, {{"vertical_water_velocity", 0.02}}));
  const double w = f.truth.at("vertical_water_velocity");
  CHECK(w > 0.002 && w < 0.02);
}

// A lagged pump: at the first inflection the displaced volume trails the
// reading, so the glider keeps diving after the pump has turned.
TEST(TruthEffects, PumpLagDeepensTheInflection) {
  auto deepest = [](const FlightResult& f) {
    double d = 0.0;
    for (const Sample& s : f.samples) d = std::max(d, s.true_depth_m);
    return d;
  };
  const double clean = deepest(fly(request(12)));
  const double lagged = deepest(fly(request(12, {{"pump_lag", 30.0}})));
  CHECK(lagged > clean + 1.0);
}
