// SPDX-License-Identifier: Apache-2.0
// The forecast's speed term (docs/forecast.md, "The speed through the
// water"): the steady-glide pitch rule, the pitch sensor's scale and the
// dead-reckoned speed it biases, the biased dead reckoning a SIL truth flies,
// the glider's files read, and the drag search on analytic speeds.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "glider/forecast/speed_term.hpp"

namespace fc = glider::forecast;
namespace fw = glider::fw;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// n steady samples of |pitch| `deg` each way, with a +-`wobble` deg alternation.
fc::GlidePitch glides(double dive_deg, double climb_deg, int n, double wobble = 0.0) {
  fc::GlidePitch g;
  for (int i = 0; i < n; ++i) {
    const double w = (i % 2 == 0 ? 1.0 : -1.0) * wobble;
    g.add(20.0, 0.12, -(dive_deg + w) * kDeg, 0.0);
    g.add(20.0, -0.12, (climb_deg + w) * kDeg, 0.0);
  }
  return g;
}

}  // namespace

TEST_GROUP(ForecastSpeedTerm){};

TEST(ForecastSpeedTerm, SteadyGlideRuleKeepsOnlySteadyGlides) {
  fc::GlidePitch g;
  g.add(20.0, 0.12, -25.0 * kDeg, 0.0);          // a dive
  g.add(20.0, -0.12, 24.0 * kDeg, 0.001);        // a climb
  g.add(2.0, 0.12, -25.0 * kDeg, 0.0);           // at the surface
  g.add(20.0, 0.01, -25.0 * kDeg, 0.0);          // hardly moving
  g.add(20.0, 0.12, -5.0 * kDeg, 0.0);           // flat: inflecting
  g.add(20.0, 0.12, -25.0 * kDeg, 0.02);         // pitching over
  g.add(20.0, -0.12, -25.0 * kDeg, 0.0);         // nose down yet rising: not a glide
  g.add(std::nan(""), 0.12, -25.0 * kDeg, 0.0);  // NaN
  g.add(20.0, 0.12, std::nan(""), 0.0);
  LONGS_EQUAL(1, g.dive_n);
  LONGS_EQUAL(1, g.climb_n);
  DOUBLES_EQUAL(25.0 * kDeg, g.dive_rad(), 1e-12);
  DOUBLES_EQUAL(24.0 * kDeg, g.climb_rad(), 1e-12);
}

TEST(ForecastSpeedTerm, ScaleIsModelOverLoggedPitchWithAFlooredSigma) {
  // The comet: m_pitch 25.6 deg where the model's trim flies 21.5.
  const fc::PitchCalibrationEstimate e =
      fc::estimate_pitch_calibration(glides(25.6, 25.6, 400), glides(21.5, 21.5, 400));
  CHECK(e.have);
  DOUBLES_EQUAL(21.5 / 25.6, e.scale, 1e-9);
  DOUBLES_EQUAL(e.scale, e.dive_scale, 1e-9);
  DOUBLES_EQUAL(fc::kPitchScaleSigmaFloor, e.scale_sigma, 1e-9);  // no spread, one scale both ways
  LONGS_EQUAL(800, e.glider_samples);
}

TEST(ForecastSpeedTerm, DiveAndClimbDisagreeingWidenTheSigma) {
  const fc::PitchCalibrationEstimate e =
      fc::estimate_pitch_calibration(glides(25.0, 27.0, 400), glides(21.5, 21.5, 400));
  CHECK(e.have);
  const double d = 21.5 / 25.0, c = 21.5 / 27.0;
  DOUBLES_EQUAL(0.5 * (d + c), e.scale, 1e-9);
  CHECK(e.scale_sigma >= 0.5 * std::fabs(d - c) - 1e-12);
  // The samples' spread too: a +-2 deg wobble is more sigma than none.
  const fc::PitchCalibrationEstimate noisy =
      fc::estimate_pitch_calibration(glides(25.6, 25.6, 60, 2.0), glides(21.5, 21.5, 400));
  CHECK(noisy.have);
  CHECK(noisy.scale_sigma > fc::kPitchScaleSigmaFloor * 1.5);
}

TEST(ForecastSpeedTerm, TooFewGlidesOrAnImplausibleScaleGiveNone) {
  CHECK_FALSE(fc::estimate_pitch_calibration(glides(25.6, 25.6, 5), glides(21.5, 21.5, 400)).have);
  CHECK_FALSE(fc::estimate_pitch_calibration(glides(25.6, 25.6, 400), fc::GlidePitch{}).have);
  CHECK_FALSE(fc::estimate_pitch_calibration(glides(45.0, 45.0, 400), glides(21.5, 21.5, 400)).have);  // x0.48
  const fc::DrSpeedCalibration none =
      fc::dr_speed_calibration(fw::DeadReckoningConfig{}, glides(25.6, 25.6, 400), fc::PitchCalibrationEstimate{});
  DOUBLES_EQUAL(1.0, none.factor, 0.0);
  DOUBLES_EQUAL(0.0, none.sigma, 0.0);
}

TEST(ForecastSpeedTerm, DeadReckonedSpeedIsLowByTheTangentsRatio) {
  // Assumed alpha 3 deg: the glider counted w / tan(25.6 + 3), the hull flew w / tan(21.5 + 3).
  const fw::DeadReckoningConfig dr;  // kAssumedAlpha
  const fc::GlidePitch logged = glides(25.6, 25.6, 400);
  const fc::PitchCalibrationEstimate e = fc::estimate_pitch_calibration(logged, glides(21.5, 21.5, 400));
  const fc::DrSpeedCalibration k = fc::dr_speed_calibration(dr, logged, e);
  const double a = dr.assumed_alpha_rad;
  DOUBLES_EQUAL(std::tan(25.6 * kDeg + a) / std::tan(21.5 * kDeg + a), k.factor, 1e-9);
  CHECK(k.factor > 1.15 && k.factor < 1.25);
  // Its sigma: the scale's moved through the same tangents (~ d factor / d scale x sigma).
  CHECK(k.sigma > 0.5 * 0.01 * k.factor && k.sigma < 3.0 * 0.01 * k.factor);
}

TEST(ForecastSpeedTerm, BiasedDeadReckoningIsTheSensorsOwn) {
  fw::DeadReckoningConfig flight_model;
  flight_model.method = fw::DrMethod::kFlightModel;
  for (std::size_t i = 0; i < fw::DeadReckoningConfig::kTableSize; ++i) {
    flight_model.dive_alpha_rad[i] = 0.09 - 0.001 * static_cast<double>(i);
    flight_model.climb_alpha_rad[i] = 0.07 - 0.0008 * static_cast<double>(i);
  }
  for (const fw::DeadReckoningConfig& given : {fw::DeadReckoningConfig{}, flight_model}) {
    for (const double scale : {0.85, 1.16}) {
      const fw::DeadReckoning truth(given), biased(fc::biased_pitch_dead_reckoning(given, scale));
      for (double deg = 14.0; deg <= 45.0; deg += 0.7) {
        for (const double sign : {-1.0, 1.0}) {
          const double p = sign * deg * kDeg, w = -sign * 0.1;
          const double want = truth.horizontal_speed(scale * p, w);
          DOUBLES_EQUAL(want, biased.horizontal_speed(p, w), 2e-3 * want);
        }
      }
    }
    // Scale 1: the config itself.
    const fw::DeadReckoning same(fc::biased_pitch_dead_reckoning(given, 1.0)), truth(given);
    DOUBLES_EQUAL(truth.horizontal_speed(-0.4, 0.1), same.horizontal_speed(-0.4, 0.1), 0.0);
  }
}

TEST(ForecastSpeedTerm, LoggedGlidesAreReadFromTheGlidersFiles) {
  const std::filesystem::path dir = std::filesystem::path(GLIDER_TEST_OUTPUT_DIR) / "forecast_speed_logged";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "from-glider");
  {
    // Yos 3-50 m at 0.12 m/s, 4 s rows, pitch 25 deg down / 24 up; then a row 100 s later (a gap).
    std::ofstream out(dir / "from-glider" / "unit.sbd.csv");
    out << "m_present_time,m_depth,m_pitch\n";
    double t = 1000.0, z = 3.5;
    int dir_sign = 1;
    for (int i = 0; i < 2000; ++i) {
      out << t << "," << z << "," << (dir_sign > 0 ? -25.0 : 24.0) * kDeg << "\n";
      t += 4.0;
      z += dir_sign * 0.48;
      if (z > 50.0 || z < 3.5) dir_sign = -dir_sign;
    }
  }
  { std::ofstream(dir / "from-glider" / "broken.csv") << "m_present_time,m_depth,m_pitch\n1,2\n"; }
  { std::ofstream(dir / "from-glider" / "science.tbd.csv") << "m_present_time,sci_water_temp\n1,12\n"; }
  std::vector<std::string> notes;
  int files = 0;
  const fc::GlidePitch g = fc::logged_glide_pitch(dir, 0.0, notes, files);
  LONGS_EQUAL(1, files);
  LONGS_EQUAL(1, static_cast<long>(notes.size()));  // the broken file, named; the science file passed over
  CHECK(notes[0].find("broken.csv") != std::string::npos);
  CHECK(g.dive_n > 800 && g.climb_n > 800);
  DOUBLES_EQUAL(25.0 * kDeg, g.dive_rad(), 1e-6);  // the file's 6 digits
  DOUBLES_EQUAL(24.0 * kDeg, g.climb_rad(), 1e-6);
  // Only the samples since a time.
  const fc::GlidePitch late = fc::logged_glide_pitch(dir, 1000.0 + 4.0 * 1500.0, notes, files);
  CHECK(late.dive_n + late.climb_n < 520 && late.dive_n + late.climb_n > 400);
}

TEST(ForecastSpeedTerm, SecantSearchFindsTheDragOfAnAnalyticSpeed) {
  // speed = 0.30 drag^-0.7: the drag that glides at 0.24 is (0.30/0.24)^(1/0.7).
  int flights = 0;
  auto fly = [&flights](double factor) {
    ++flights;
    return fc::SpeedFlight{0.30 * std::pow(factor, -0.7), 0.3};
  };
  const fc::SpeedMatch m = fc::match_speed(0.24, fly(1.0), fly);
  DOUBLES_EQUAL(1.0, m.ratio, 0.01);
  DOUBLES_EQUAL(std::pow(0.30 / 0.24, 1.0 / 0.7), m.factor, 0.03);
  CHECK(m.flights <= 6);
  DOUBLES_EQUAL(-0.7, m.slope, 0.05);
  // Within 1 % already: no flight.
  const fc::SpeedMatch none = fc::match_speed(0.301, fc::SpeedFlight{0.30, 0.3}, fly);
  LONGS_EQUAL(0, none.flights);
  DOUBLES_EQUAL(1.0, none.factor, 0.0);
  // Out of reach: held at the limit, the best kept.
  const fc::SpeedMatch far = fc::match_speed(0.05, fly(1.0), fly);
  DOUBLES_EQUAL(fc::kSpeedDragMax, far.factor, 1e-12);
  // No glide beyond x1.2: the nominal kept when nothing flew nearer.
  auto stalls = [](double factor) { return fc::SpeedFlight{factor > 1.2 ? 0.0 : 0.30 * std::pow(factor, -0.7), 0.3}; };
  const fc::SpeedMatch stalled = fc::match_speed(0.10, stalls(1.0), stalls);
  CHECK(stalled.factor <= 1.2);
}
