#include <CppUTest/TestHarness.h>

#include <cmath>

#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

TEST_GROUP(SteadyGlide) {
  VehicleParams v = load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  const double rho = 1025.0;
  const double gravity = 9.81;
};

// Paper 000, Fig. 13: with the identified parameters and m0 = 250 g, a 25 deg
// glide path gives ~0.20 m/s depth rate and ~0.42 m/s horizontal speed.
TEST(SteadyGlide, Paper000Figure13) {
  const SteadyGlideResult r = steady_glide_for_path(v.hydro, rho, 25.0, 0.250);
  CHECK_TRUE(r.glide.has_value());
  const SteadyGlide& g = *r.glide;
  CHECK(std::abs(g.depth_rate_m_s - 0.20) <= 0.10 * 0.20);
  CHECK(std::abs(g.horizontal_speed_m_s - 0.42) <= 0.10 * 0.42);
  DOUBLES_EQUAL(-25.0 * M_PI / 180.0, g.glide_path_rad, 1e-12);
  DOUBLES_EQUAL(g.speed_m_s * std::sin(25.0 * M_PI / 180.0), g.depth_rate_m_s, 1e-12);
}

TEST(SteadyGlide, SatisfiesTheEquilibriumEquations) {
  const SteadyGlide g = *steady_glide_for_path(v.hydro, rho, 30.0, 0.2).glide;
  const double q = 0.5 * rho * v.hydro.reference_area_m2 * g.speed_m_s * g.speed_m_s;
  const double cl = 11.76 * g.alpha_rad + 4.6 * g.alpha_rad * std::abs(g.alpha_rad);
  const double cd = 0.214 + 32.3 * g.alpha_rad * g.alpha_rad;
  const double w = 0.2 * gravity;
  // 000 eqs. 4-5 at theta = xi + alpha.
  DOUBLES_EQUAL(0.0, q * cl * std::sin(g.alpha_rad) - q * cd * std::cos(g.alpha_rad) - w * std::sin(g.pitch_rad),
                1e-9);
  DOUBLES_EQUAL(0.0, q * cl * std::cos(g.alpha_rad) + q * cd * std::sin(g.alpha_rad) - w * std::cos(g.pitch_rad),
                1e-9);
}

TEST(SteadyGlide, ClimbMirrorsDive) {
  const SteadyGlide dive = *steady_glide_for_path(v.hydro, rho, 25.0, 0.25).glide;
  const SteadyGlide climb = *steady_glide_for_path(v.hydro, rho, 25.0, -0.25).glide;
  DOUBLES_EQUAL(-dive.alpha_rad, climb.alpha_rad, 1e-12);
  DOUBLES_EQUAL(-dive.pitch_rad, climb.pitch_rad, 1e-12);
  DOUBLES_EQUAL(-dive.depth_rate_m_s, climb.depth_rate_m_s, 1e-12);
  DOUBLES_EQUAL(dive.horizontal_speed_m_s, climb.horizontal_speed_m_s, 1e-12);
  CHECK(dive.alpha_rad > 0.0 && dive.pitch_rad < 0.0);
}

TEST(SteadyGlide, TooShallowIsRefused) {
  const double best = min_glide_path_deg(v.hydro);
  CHECK(best > 10.0 && best < 25.0);
  const SteadyGlideResult r = steady_glide_for_path(v.hydro, rho, best - 0.5, 0.25);
  CHECK_FALSE(r.glide.has_value());
  CHECK(r.error.find("shallower") != std::string::npos);
  CHECK_FALSE(steady_glide_for_path(v.hydro, rho, 25.0, 0.0).glide.has_value());
}
