// SPDX-License-Identifier: Apache-2.0
// A zero-lift drag that falls with speed, C_D0 (V / V_ref)^-n: the factor,
// its file keys, the steady glides (the fixed point in the speed) and the
// dynamic model settling on them.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/model/dynamics.hpp"
#include "glider/model/hydrodynamics.hpp"
#include "glider/model/prescribed_pitch.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

namespace {

VehicleParams shallow() { return load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml"); }

VehicleParams with_exponent(double n) {
  VehicleParams v = shallow();
  v.hydro.cd0_reynolds_exponent = n;
  return v;
}

// Lift and drag at the glide's own speed (the model's force law, not the
// solver's): their sum must carry the net weight along the glide path.
void check_force_balance(const Hydrodynamics& h, const SteadyGlide& g, double rho) {
  const double v1 = g.speed_m_s * std::cos(g.alpha_rad), v3 = g.speed_m_s * std::sin(g.alpha_rad);
  const FlowForces f = flow_forces(h, rho, v1, v3);
  const double w = g.net_buoyancy_kg * 9.81;
  // Body axes: the weight's components at pitch theta balance the flow's.
  DOUBLES_EQUAL(0.0, f.f1 - w * std::sin(g.pitch_rad), 1e-7);
  DOUBLES_EQUAL(0.0, f.f3 + w * std::cos(g.pitch_rad), 1e-7);
}

std::string vehicle_error(const std::string& line) {
  std::string text;
  {
    std::FILE* f = std::fopen(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml", "rb");
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
  }
  const std::string anchor = "cd0 = ";
  const std::size_t at = text.find(anchor);
  text.insert(at, line + "\n");
  try {
    parse_vehicle_text(text, "reynolds.toml");
  } catch (const glider::config::ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_GROUP(ReynoldsDrag){};

TEST(ReynoldsDrag, FactorIsExactlyOneWithoutTheTermAndFollowsThePowerLaw) {
  Hydrodynamics h = shallow().hydro;
  CHECK_EQUAL(0.0, h.cd0_reynolds_exponent);  // vehicles fly the file's drag unless they say otherwise
  CHECK_EQUAL(1.0, skin_friction_factor(h, 0.7));
  h.cd0_reynolds_exponent = 0.2;
  h.cd0_reference_speed_m_s = 0.35;
  DOUBLES_EQUAL(1.0, skin_friction_factor(h, 0.35), 1e-15);
  DOUBLES_EQUAL(std::pow(2.0, -0.2), skin_friction_factor(h, 0.70), 1e-15);
  // Turbulent flat plate (C_f ~ Re^-0.2): twice the speed, 13 % less friction coefficient.
  DOUBLES_EQUAL(0.8706, skin_friction_factor(h, 0.70), 1e-4);
  // At rest the factor stays finite: the speed floor.
  CHECK(std::isfinite(skin_friction_factor(h, 0.0)));
  DOUBLES_EQUAL(skin_friction_factor(h, kSkinFrictionMinSpeedMS), skin_friction_factor(h, 0.0), 0.0);
}

TEST(ReynoldsDrag, FastFactorMatchesThePowerLaw) {
  for (double n : {0.05, 0.1, 0.2, 0.5}) {
    Hydrodynamics h = shallow().hydro;
    h.cd0_reynolds_exponent = n;
    const SkinFrictionFactor fast(h);
    double worst = 0.0;
    // Slowly changing speeds (a flight's stages) and jumps (a new flight).
    for (double v = 0.0; v < 3.5; v += 0.000737) {
      worst = std::max(worst, std::abs(fast(v) / skin_friction_factor(h, v) - 1.0));
    }
    for (int i = 0; i < 2000; ++i) {
      const double v = 0.05 + 0.6 * std::fmod(i * 0.61803398875, 1.0);
      worst = std::max(worst, std::abs(fast(v) / skin_friction_factor(h, v) - 1.0));
    }
    // The series' remainder n(n+1)(n+2)(n+3)(n+4)/120 d^5 at |d| = 0.01:
    // 2.5e-12 for n = 0.1, 2.5e-11 for n = 0.5.
    const double bound = n * (n + 1) * (n + 2) * (n + 3) * (n + 4) / 120.0 * std::pow(0.01, 5) * 1.05 + 1e-14;
    CHECK_TRUE(worst < bound);
  }
  const SkinFrictionFactor off(shallow().hydro);
  CHECK_EQUAL(1.0, off(0.3));
}

TEST(ReynoldsDrag, FileKeysReadWithRangesAndRefuseNaN) {
  STRCMP_EQUAL("", vehicle_error("cd0_reynolds_exponent = 0.15\ncd0_reference_speed_m_s = 0.46").c_str());
  const std::string nan = vehicle_error("cd0_reynolds_exponent = nan");
  STRCMP_CONTAINS("hydrodynamics.cd0_reynolds_exponent", nan.c_str());
  const std::string high = vehicle_error("cd0_reynolds_exponent = 0.9");
  STRCMP_CONTAINS("hydrodynamics.cd0_reynolds_exponent", high.c_str());
  STRCMP_CONTAINS("0.5", high.c_str());
  STRCMP_CONTAINS("hydrodynamics.cd0_reference_speed_m_s", vehicle_error("cd0_reference_speed_m_s = 0").c_str());
  // Written and read back (the extended vehicle, a log's vehicle.* metadata).
  VehicleParams v = with_exponent(0.15);
  v.hydro.cd0_reference_speed_m_s = 0.46;
  const VehicleParams back = parse_vehicle_text(vehicle_file_text(v), "back.toml");
  DOUBLES_EQUAL(0.15, back.hydro.cd0_reynolds_exponent, 0.0);
  DOUBLES_EQUAL(0.46, back.hydro.cd0_reference_speed_m_s, 0.0);
}

TEST(ReynoldsDrag, SteadyGlideAtPitchBalancesTheForcesAtItsOwnSpeed) {
  const double rho = 1025.0, pitch = -0.40;
  for (double n : {0.1, 0.2, 0.5}) {
    const VehicleParams v = with_exponent(n);
    for (double m0 : {0.05, 0.15, 0.40, -0.15}) {
      const double p = m0 > 0.0 ? pitch : -pitch;
      const SteadyGlideResult r = steady_glide_for_pitch(v.hydro, rho, p, m0);
      CHECK_TRUE(r.glide.has_value());
      check_force_balance(v.hydro, *r.glide, rho);
      DOUBLES_EQUAL(p, r.glide->pitch_rad, 1e-9);
      // The many-sample solver gives the same glide.
      const SteadyGlideResult s = PitchGlideSolver(v.hydro).solve(rho, p, m0);
      DOUBLES_EQUAL(r.glide->speed_m_s, s.glide->speed_m_s, 1e-9);
    }
  }
}

TEST(ReynoldsDrag, FasterThanTheReferenceFliesFasterSlowerFliesSlower) {
  const double rho = 1025.0;
  const VehicleParams off = shallow();
  const VehicleParams on = with_exponent(0.2);
  // Heavy: faster than 0.35 m/s, the skin friction falls and the glide is faster still.
  const SteadyGlide fast_off = *steady_glide_for_pitch(off.hydro, rho, -0.45, 0.45).glide;
  const SteadyGlide fast_on = *steady_glide_for_pitch(on.hydro, rho, -0.45, 0.45).glide;
  CHECK_TRUE(fast_off.speed_m_s > 0.40);
  CHECK_TRUE(fast_on.speed_m_s > fast_off.speed_m_s);
  // Nearly neutral: slower than the reference, more drag, slower still.
  const SteadyGlide slow_off = *steady_glide_for_pitch(off.hydro, rho, -0.45, 0.03).glide;
  const SteadyGlide slow_on = *steady_glide_for_pitch(on.hydro, rho, -0.45, 0.03).glide;
  CHECK_TRUE(slow_off.speed_m_s < 0.30);
  CHECK_TRUE(slow_on.speed_m_s < slow_off.speed_m_s);
}

TEST(ReynoldsDrag, GlideForPathAndTrimBalanceAtTheirSpeed) {
  const VehicleParams v = with_exponent(0.2);
  const SteadyGlideResult r = steady_glide_for_path(v.hydro, 1025.0, 25.0, 0.25);
  CHECK_TRUE(r.glide.has_value());
  check_force_balance(v.hydro, *r.glide, 1025.0);
  DOUBLES_EQUAL(-25.0 * M_PI / 180.0, r.glide->glide_path_rad, 1e-12);
}

TEST(ReynoldsDrag, EquilibriumOfTheFullModelBalancesForcesAndMoment) {
  const VehicleParams v = with_exponent(0.2);
  const GliderDynamics dyn(v, still_water(1025.0));
  const TrimResult trim = solve_trim(dyn, 25.0, 0.2, 50.0);
  CHECK_TRUE(trim.trim.has_value());
  MassInputs masses;
  masses.pumped_volume_m3 = trim.trim->pumped_volume_m3;
  masses.battery_pos_m = trim.trim->battery_pos_m;
  const SteadyGlideResult eq = solve_equilibrium(dyn, masses, 50.0);
  CHECK_TRUE(eq.glide.has_value());
  // The trim's glide, found again by the forward solver.
  DOUBLES_EQUAL(trim.trim->glide.speed_m_s, eq.glide->speed_m_s, 1e-6);
  DOUBLES_EQUAL(trim.trim->glide.pitch_rad, eq.glide->pitch_rad, 1e-6);
  check_force_balance(v.hydro, *eq.glide, 1025.0);
}

TEST(ReynoldsDrag, PrescribedPitchDynamicsRestsOnTheSteadyGlide) {
  // The diagnosis's dynamic model at the steady glide's velocities: no
  // acceleration (both models fly the same drag at the same speed).
  for (double n : {0.0, 0.1, 0.3}) {
    const VehicleParams v = with_exponent(n);
    const PrescribedPitchDynamics dyn(v);
    PrescribedPitchInputs in;
    in.theta_rad = -0.42;
    in.depth_m = 30.0;
    in.density_kg_m3 = v.trim_density_kg_m3;
    in.pumped_volume_m3 = -200e-6;  // water taken in: heavy, a dive
    const double m0 = dyn.net_buoyancy_kg(in);
    CHECK_TRUE(m0 > 0.0);
    const SteadyGlide g = *steady_glide_for_pitch(v.hydro, in.density_kg_m3, in.theta_rad, m0).glide;
    const auto p = dyn.impulse(g.speed_m_s * std::cos(g.alpha_rad), g.speed_m_s * std::sin(g.alpha_rad), in);
    const auto d = dyn.derivative(p, in);
    DOUBLES_EQUAL(0.0, d.p_dot[0], 1e-6);
    DOUBLES_EQUAL(0.0, d.p_dot[1], 1e-6);
    DOUBLES_EQUAL(g.depth_rate_m_s, d.depth_rate_m_s, 1e-9);
  }
}
