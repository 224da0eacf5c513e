// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>

#include "glider/model/ctd_profile.hpp"
#include "glider/model/simulator.hpp"
#include "glider/model/stable_step.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

namespace {

VehicleParams slocum() { return load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml"); }

Eigen::Matrix<double, 6, 6> jacobian(const GliderDynamics& dyn, const State& s, const MassInputs& m) {
  return dynamics_jacobian(dyn, s, m);
}

// Fly with fixed controls until steady.
GliderSimulator steady_glide(const VehicleParams& v, double pumped_m3, double battery_m,
                             const Environment& env = Environment{}) {
  GliderSimulator sim(v, env);
  sim.reset_at_depth(200.0, pumped_m3, battery_m);
  sim.advance(900.0);
  return sim;
}

// A state gliding at the given body velocities, 30 m deep.
Evaluation glide_at(const GliderDynamics& dyn, const MassInputs& m, double v1 = 0.45, double v3 = 0.025) {
  return dyn.evaluate(0.0, dyn.make_state(30.0, -0.4, v1, v3, 0.0, m), m);
}

}  // namespace

TEST_GROUP(Dynamics) { VehicleParams v = slocum(); };

TEST(Dynamics, NeutralAndTrimmedStaysAtRest) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{};  // zero ballast, battery at zero: level by construction
  DOUBLES_EQUAL(0.0, dyn.static_pitch_rad(m), 1e-4);
  const State s = dyn.make_state(30.0, dyn.static_pitch_rad(m), 0.0, 0.0, 0.0, m);
  const Evaluation e = dyn.evaluate(0.0, s, m);
  DOUBLES_EQUAL(0.0, e.net_buoyancy_kg, 1e-9);
  CHECK(e.state_dot.cwiseAbs().maxCoeff() < 1e-9);
}

TEST(Dynamics, ImpulseRoundTrip) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{-200e-6, 0.01, 0.001, 0.0, 0.0, 0.0};
  const Evaluation e = dyn.evaluate(0.0, dyn.make_state(20.0, -0.4, 0.4, 0.02, -0.01, m), m);
  DOUBLES_EQUAL(0.4, e.v1, 1e-12);
  DOUBLES_EQUAL(0.02, e.v3, 1e-12);
  DOUBLES_EQUAL(-0.01, e.q, 1e-12);
}

TEST(Dynamics, MunkMomentIsAddedMassDifference) {
  GliderDynamics dyn(v, Environment{});
  const Evaluation e = glide_at(dyn, MassInputs{});
  // Paper 000 eq. 3: (m_f3 - m_f1) v1 v3; destabilising (nose up for v3 > 0).
  DOUBLES_EQUAL((v.added_mass_z_kg - v.added_mass_x_kg) * 0.45 * 0.025, e.munk_moment_nm, 1e-12);
  VehicleParams no_added = v;
  no_added.added_mass_x_kg = no_added.added_mass_z_kg = 0.0;
  DOUBLES_EQUAL(0.0, glide_at(GliderDynamics(no_added, Environment{}), MassInputs{}).munk_moment_nm, 1e-12);
}

TEST(Dynamics, HeavyAtRestSinksAndBallastPitchesNoseDown) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{-250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};  // 250 cc in: heavy, nose heavy
  CHECK(dyn.static_pitch_rad(m) < -0.3);
  const Evaluation e = dyn.evaluate(0.0, dyn.make_state(30.0, 0.0, 0.0, 0.0, 0.0, m), m);
  DOUBLES_EQUAL(0.25625, e.net_buoyancy_kg, 1e-9);  // 250 cc of 1025 kg/m^3 water
  CHECK(e.state_dot[kP3] > 0.0);                    // pushed down
  CHECK(e.state_dot[kPi2] < 0.0);                   // nose down
}

TEST(Dynamics, HullCompressibilityMakesItHeavierWithDepthExactly) {
  VehicleParams soft = v;
  soft.hull_compressibility_per_pa = 3e-10;
  const MassInputs m{};
  const GliderDynamics rigid_dyn(v, Environment{});
  const GliderDynamics soft_dyn(soft, Environment{});
  const double depth = 100.0;
  const State s = rigid_dyn.make_state(depth, 0.0, 0.0, 0.0, 0.0, m);
  const double pressure_pa = 1025.0 * 9.81 * depth;
  const double expected = 1025.0 * displaced_volume_m3(v) * 3e-10 * pressure_pa;  // ~ +15 g
  DOUBLES_EQUAL(expected, soft_dyn.evaluate(0.0, s, m).net_buoyancy_kg - rigid_dyn.evaluate(0.0, s, m).net_buoyancy_kg,
                1e-12);
  CHECK(expected > 0.01 && expected < 0.02);  // a realistic ~15 g at 100 m
}

TEST(Dynamics, ThermalExpansionMakesItLighterInWarmWater) {
  VehicleParams expanding = v;
  expanding.hull_thermal_expansion_per_k = 7e-5;
  const Environment warm{WaterColumn(1025.0, expanding.hull_reference_temperature_c + 5.0)};
  const MassInputs m{};
  const GliderDynamics a(v, warm);
  const GliderDynamics b(expanding, warm);
  const State s = a.make_state(50.0, 0.0, 0.0, 0.0, 0.0, m);
  DOUBLES_EQUAL(-1025.0 * displaced_volume_m3(v) * 7e-5 * 5.0,
                b.evaluate(0.0, s, m).net_buoyancy_kg - a.evaluate(0.0, s, m).net_buoyancy_kg, 1e-12);
}

TEST(Dynamics, DenserWaterMakesItLighter) {
  const MassInputs m{};
  const GliderDynamics nominal(v, still_water(1025.0));
  const GliderDynamics dense(v, still_water(1027.0));
  const State s = nominal.make_state(50.0, 0.0, 0.0, 0.0, 0.0, m);
  DOUBLES_EQUAL(-2.0 * displaced_volume_m3(v),
                dense.evaluate(0.0, s, m).net_buoyancy_kg - nominal.evaluate(0.0, s, m).net_buoyancy_kg, 1e-9);
}

TEST(Dynamics, WaterVelocityAddsToPositionRatesOnly) {
  const std::vector<ProfileNode> nodes{{0.0, {1025.0, 10.0, 0.1, -0.05, 0.02}},
                                       {100.0, {1025.0, 10.0, 0.3, -0.05, 0.02}}};
  const Environment moving{WaterColumn(nodes, Oscillation{})};
  const MassInputs m{-250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};
  const GliderDynamics still(v, Environment{});
  const GliderDynamics flowing(v, moving);
  const State s = still.make_state(50.0, -0.4, 0.45, 0.02, 0.01, m);
  const Evaluation a = still.evaluate(0.0, s, m);
  const Evaluation b = flowing.evaluate(0.0, s, m);
  DOUBLES_EQUAL(0.2, b.state_dot[kEast] - a.state_dot[kEast], 1e-12);  // current at 50 m, interpolated
  DOUBLES_EQUAL(-0.05, b.state_dot[kNorth] - a.state_dot[kNorth], 1e-12);
  DOUBLES_EQUAL(0.02, b.state_dot[kZ] - a.state_dot[kZ], 1e-12);
  for (int k : {kTheta, kP1, kP3, kPi2, kYawRate}) DOUBLES_EQUAL(a.state_dot[k], b.state_dot[k], 0.0);
  // The current's shear (0.2 m/s over 100 m, east: starboard of a north
  // heading) turns the glider crossing it: -depth rate x shear / V.
  DOUBLES_EQUAL(0.0, s[kPsi], 0.0);
  DOUBLES_EQUAL(-b.state_dot[kZ] * 0.002 / b.speed_m_s, b.state_dot[kPsi] - a.state_dot[kPsi], 1e-12);
}

// A rolled glider that pitches turns: heading rate = pitch rate tan(roll) / cos(pitch).
TEST(Dynamics, PitchingWhileRolledTurnsTheHeading) {
  VehicleParams rolled = v;
  rolled.heading.roll_offset_rad = -0.17;
  const MassInputs m{-250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};
  const GliderDynamics level(v, Environment{});
  const GliderDynamics tilted(rolled, Environment{});
  const State s = level.make_state(50.0, -0.4, 0.45, 0.02, 0.03, m);
  const Evaluation a = level.evaluate(0.0, s, m);
  const Evaluation b = tilted.evaluate(0.0, s, m);
  CHECK(std::abs(b.q) > 1e-3);
  DOUBLES_EQUAL(a.q, b.q, 0.0);  // the roll leaves the vertical plane alone
  DOUBLES_EQUAL(b.q * (std::tan(-0.17) - std::tan(v.heading.roll_offset_rad)) / std::cos(-0.4),
                b.state_dot[kPsi] - a.state_dot[kPsi], 1e-12);
}

TEST(Dynamics, OscillatingWaterFollowsItsPeriod) {
  const Environment tidal{WaterColumn({{0.0, {}}}, Oscillation{600.0, 0.0, 0.1, 0.0, 0.01})};
  DOUBLES_EQUAL(0.1, tidal.water.at(10.0, 150.0).current_east_m_s, 1e-12);
  DOUBLES_EQUAL(-0.01, tidal.water.at(10.0, 450.0).vertical_velocity_m_s, 1e-12);
}

TEST(Dynamics, SecondMovingMassCouplesLikeTheBattery) {
  VehicleParams two = v;
  two.second_mass = {1.0, 0.0, 0.02, -0.1, 0.1, 0.01};
  two.hull_mass_kg -= 1.0;  // same total mass, same displacement
  GliderDynamics dyn(two, Environment{});
  MassInputs m{};
  const double level = dyn.static_pitch_rad(m);
  m.second_pos_m = 0.05;  // forward: nose down
  CHECK(dyn.static_pitch_rad(m) < level - 0.05);
  // Its motion carries impulse: velocities at equal impulse change.
  m.second_rate_m_s = 0.01;
  const State s = dyn.make_state(30.0, 0.0, 0.3, 0.0, 0.0, MassInputs{});
  CHECK(std::abs(dyn.evaluate(0.0, s, m).v1 - 0.3) > 1e-5);
}

TEST(Dynamics, FinAndRollSetTheYawRate) {
  const MassInputs straight{-250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};
  MassInputs finned = straight;
  finned.fin_rad = 0.2;
  GliderDynamics dyn(v, Environment{});
  const Evaluation e = glide_at(dyn, finned);
  // Steady yaw rate (state at zero yaw rate: rate of change = target / tau).
  DOUBLES_EQUAL(v.heading.fin_yaw_gain_per_m * e.speed_m_s * 0.2, e.state_dot[kYawRate] * v.heading.yaw_time_constant_s,
                1e-12);
  DOUBLES_EQUAL(0.0, glide_at(dyn, straight).state_dot[kYawRate], 0.0);
  VehicleParams rolled = v;
  rolled.heading.roll_offset_rad = -0.1745;  // comet-2019: port wing down
  GliderDynamics rolled_dyn(rolled, Environment{});
  const double dive = glide_at(rolled_dyn, straight, 0.45, 0.025).state_dot[kYawRate];
  const double climb = glide_at(rolled_dyn, straight, 0.45, -0.025).state_dot[kYawRate];
  CHECK(dive > 0.0);  // turns clockwise on dives, as the real data need a negative fin
  DOUBLES_EQUAL(-dive, climb, 1e-12);
}

TEST(Dynamics, FloatsAtTheSurface) {
  GliderSimulator sim(v, Environment{});
  sim.reset_at_surface(250e-6, 0.0);
  const double z0 = sim.state()[kZ];
  CHECK(z0 > 0.0 && z0 < v.hull_diameter_m / 2.0);
  sim.advance(120.0);
  DOUBLES_EQUAL(z0, sim.state()[kZ], 1e-3);
}

TEST(Dynamics, SettlesOnTheSteadyGlideSolution) {
  for (double pumped : {-250e-6, 250e-6}) {
    GliderSimulator sim = steady_glide(v, pumped, 0.0);
    const Truth t = sim.truth();
    // The full dynamics at rest in a glide satisfy the equilibrium equations
    // (000 eqs. 4-5) that the steady solver solves.
    const SteadyGlideResult steady =
        steady_glide_for_path(v.hydro, 1025.0, std::abs(t.glide_path_rad) * 180.0 / M_PI, t.net_buoyancy_kg);
    CHECK_TRUE(steady.glide.has_value());
    DOUBLES_EQUAL(steady.glide->alpha_rad, t.alpha_rad, 1e-5);
    DOUBLES_EQUAL(steady.glide->speed_m_s, t.speed_m_s, 1e-5);
    DOUBLES_EQUAL(steady.glide->depth_rate_m_s, t.depth_rate_m_s, 1e-5);
    DOUBLES_EQUAL(0.0, t.pitch_rate_rad_s, 1e-7);
  }
}

TEST(Dynamics, StepSizeIsWellInsideRk4Limits) {
  // The justification of GliderSimulator's steps, checked: the linearized
  // glide is stable and |lambda| h stays inside RK4's stability limit (2.8
  // on the negative real axis) with a margin, for all modes: the submerged
  // step in a glide, the surface step floating at the surface.
  for (double pumped : {-250e-6, 250e-6}) {
    GliderSimulator sim = steady_glide(v, pumped, 0.0);
    const MassInputs m{pumped, 0.0, 0.0, 0.0, 0.0, 0.0};
    const Eigen::EigenSolver<Eigen::Matrix<double, 6, 6>> solver(jacobian(sim.dynamics(), sim.state(), m));
    for (int i = 0; i < 6; ++i) {
      const std::complex<double> lambda = solver.eigenvalues()[i];
      CHECK(lambda.real() < 1e-9);  // a steady glide is (at worst neutrally) stable
      CHECK(std::abs(lambda) * GliderSimulator::kDefaultStepS < 1.5);
    }
  }
  GliderSimulator floating(v, Environment{});
  floating.reset_at_surface(250e-6, 0.0);
  const MassInputs m{250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};
  const Eigen::EigenSolver<Eigen::Matrix<double, 6, 6>> solver(jacobian(floating.dynamics(), floating.state(), m));
  double fastest = 0.0;
  for (int i = 0; i < 6; ++i) {
    const std::complex<double> lambda = solver.eigenvalues()[i];
    CHECK(lambda.real() < 1e-9);
    CHECK(std::abs(lambda) * GliderSimulator::kSurfaceStepS < 1.5);
    fastest = std::max(fastest, std::abs(lambda));
  }
  // Why the surface has its own step: the submerged one would not do there.
  CHECK(fastest * GliderSimulator::kDefaultStepS > 1.5);
}

TEST(Dynamics, HalvingTheStepChangesLittle) {
  auto fly = [this](double step) {
    GliderSimulator sim(v, Environment{}, step);
    sim.reset_at_depth(100.0, 0.0, 0.0);
    sim.command_pumped_volume_m3(-250e-6);
    sim.command_battery_pos_m(0.005);
    sim.command_fin_rad(0.1);
    sim.advance(300.0);
    return sim.state();
  };
  // The 0.1 s step (near the surface; everywhere before the submerged step
  // grew). The 1 s submerged step against 0.01 s: test_integration_accuracy.cpp.
  const State coarse = fly(GliderSimulator::kSurfaceStepS);
  const State fine = fly(GliderSimulator::kSurfaceStepS / 2.0);
  DOUBLES_EQUAL(fine[kZ], coarse[kZ], 1e-4);
  DOUBLES_EQUAL(fine[kTheta], coarse[kTheta], 1e-6);
  DOUBLES_EQUAL(fine[kPsi], coarse[kPsi], 1e-5);
}

TEST(Dynamics, BatteryForwardPitchesDown) {
  GliderSimulator aft = steady_glide(v, -250e-6, -0.0127);
  GliderSimulator fwd = steady_glide(v, -250e-6, 0.0127);
  CHECK(fwd.truth().pitch_rad < aft.truth().pitch_rad - 0.2);
}

TEST(Dynamics, PitchDampingIsExactlyItsRateTerm) {
  const MassInputs m{-250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};
  VehicleParams undamped = v;
  undamped.hydro.cmq_m2 = 0.0;
  const GliderDynamics with(v, Environment{});
  const GliderDynamics without(undamped, Environment{});
  const State s = with.make_state(30.0, -0.4, 0.45, 0.02, 0.03, m);
  const Evaluation a = with.evaluate(0.0, s, m);
  const Evaluation b = without.evaluate(0.0, s, m);
  DOUBLES_EQUAL(0.5 * 1025.0 * v.hydro.reference_area_m2 * a.speed_m_s * v.hydro.cmq_m2 * a.q,
                a.hydro_moment_nm - b.hydro_moment_nm, 1e-12);
  CHECK(a.hydro_moment_nm - b.hydro_moment_nm < 0.0);  // opposes the nose-up rate
  for (int k : {kEast, kNorth, kZ, kTheta, kP1, kP3}) DOUBLES_EQUAL(a.state_dot[k], b.state_dot[k], 0.0);
}

TEST(Dynamics, LiftAndDragAreTheOnlyForcesOfTheFlow) {
  VehicleParams no_flow = v;
  no_flow.hydro.cl_alpha = no_flow.hydro.cl_alpha_abs_alpha = 0.0;
  no_flow.hydro.cd0 = 1e-300;  // validate() wants it positive; numerically zero
  no_flow.hydro.cd_alpha2 = no_flow.hydro.crossflow_cn90 = 0.0;
  const MassInputs m{-250e-6, 0.0, 0.0, 0.0, 0.0, 0.0};
  const GliderDynamics flow(v, Environment{});
  const GliderDynamics none(no_flow, Environment{});
  const State s = flow.make_state(30.0, -0.4, 0.45, 0.02, 0.0, m);
  const Evaluation a = flow.evaluate(0.0, s, m);
  const Evaluation b = none.evaluate(0.0, s, m);
  const double ca = std::cos(a.alpha_rad), sa = std::sin(a.alpha_rad);
  DOUBLES_EQUAL(a.lift_n * sa - a.drag_n * ca, a.state_dot[kP1] - b.state_dot[kP1], 1e-12);
  DOUBLES_EQUAL(-a.lift_n * ca - a.drag_n * sa, a.state_dot[kP3] - b.state_dot[kP3], 1e-12);
  DOUBLES_EQUAL(0.0, b.lift_n, 1e-300);
}

TEST(Dynamics, WaterColumnFromCtdFollowsTeos10) {
  // A Baltic-like stratification: warm fresh water over cold saltier water.
  std::vector<CtdSample> casts;
  for (int i = 0; i <= 400; ++i) {
    const double depth = 0.1 * i;
    const bool deep = depth > 20.0;
    casts.push_back({depth, deep ? 5.5 : 17.0, deep ? 0.95 : 1.1, depth});
  }
  const WaterColumn column = water_column_from_ctd(casts, 1.0);
  const double top = column.at(5.0, 0.0).density_kg_m3;
  const double bottom = column.at(35.0, 0.0).density_kg_m3;
  CHECK(top > 1003.0 && top < 1006.0);  // comet-2016's Baltic: 1004.5 ...
  CHECK(bottom > top + 1.0);            // ... to 1007 kg/m^3 in the cold deep layer
  DOUBLES_EQUAL(17.0, column.at(5.0, 0.0).temperature_c, 1e-12);
}
