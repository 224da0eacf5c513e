#include <CppUTest/TestHarness.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "glider/model/simulator.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/model/vehicle_file.hpp"

using namespace glider::model;

namespace {

VehicleParams slocum() { return load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml"); }

// Jacobian of the state derivative (finite differences) without x, which
// nothing depends on.
Eigen::Matrix<double, 5, 5> jacobian(const GliderDynamics& dyn, const State& s, const MassInputs& m) {
  Eigen::Matrix<double, 5, 5> j;
  for (int col = 0; col < 5; ++col) {
    const double h = 1e-6 * std::max(1.0, std::abs(s[col + 1]));
    State plus = s;
    State minus = s;
    plus[col + 1] += h;
    minus[col + 1] -= h;
    const State d = (dyn.derivative(plus, m) - dyn.derivative(minus, m)) / (2.0 * h);
    j.col(col) = d.tail<5>();
  }
  return j;
}

// Fly with fixed controls until steady.
GliderSimulator steady_dive(const VehicleParams& v, double pumped_m3, double battery_m) {
  GliderSimulator sim(v, Environment{});
  sim.reset_at_depth(200.0, pumped_m3, battery_m);
  sim.advance(900.0);
  return sim;
}

}  // namespace

TEST_GROUP(Dynamics) {
  VehicleParams v = slocum();
};

TEST(Dynamics, NeutralAndTrimmedStaysAtRest) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{};  // zero ballast, battery at zero: level by construction
  DOUBLES_EQUAL(0.0, dyn.static_pitch_rad(m), 1e-4);
  const State s = dyn.make_state(0.0, 30.0, dyn.static_pitch_rad(m), 0.0, 0.0, 0.0, m);
  const Evaluation e = dyn.evaluate(s, m);
  DOUBLES_EQUAL(0.0, e.net_buoyancy_kg, 1e-9);
  CHECK(e.state_dot.cwiseAbs().maxCoeff() < 1e-9);
}

TEST(Dynamics, ImpulseRoundTrip) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{-200e-6, 0.01, 0.001};
  const State s = dyn.make_state(1.0, 20.0, -0.4, 0.4, 0.02, -0.01, m);
  const Evaluation e = dyn.evaluate(s, m);
  DOUBLES_EQUAL(0.4, e.v1, 1e-12);
  DOUBLES_EQUAL(0.02, e.v3, 1e-12);
  DOUBLES_EQUAL(-0.01, e.q, 1e-12);
}

TEST(Dynamics, MunkMomentIsAddedMassDifference) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{};
  const double v1 = 0.45, v3 = 0.03;
  const State s = dyn.make_state(0.0, 30.0, -0.4, v1, v3, 0.0, m);
  const Evaluation e = dyn.evaluate(s, m);
  // Paper 000 eq. 3: (m_f3 - m_f1) v1 v3; destabilising (nose up for v3 > 0).
  DOUBLES_EQUAL((v.added_mass_z_kg - v.added_mass_x_kg) * v1 * v3, e.munk_moment_nm, 1e-12);
}

TEST(Dynamics, HeavyAtRestSinksAndBallastPitchesNoseDown) {
  GliderDynamics dyn(v, Environment{});
  const MassInputs m{-250e-6, 0.0, 0.0};  // 250 cc in: heavy, nose heavy
  CHECK(dyn.static_pitch_rad(m) < -0.3);
  const State s = dyn.make_state(0.0, 30.0, 0.0, 0.0, 0.0, 0.0, m);
  const Evaluation e = dyn.evaluate(s, m);
  DOUBLES_EQUAL(0.25625, e.net_buoyancy_kg, 1e-9);  // 250 cc of 1025 kg/m^3 water
  CHECK(e.state_dot[kP3] > 0.0);    // pushed down
  CHECK(e.state_dot[kPi2] < 0.0);   // nose down
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
  GliderSimulator sim = steady_dive(v, -250e-6, 0.0);
  const Truth t = sim.truth();
  CHECK(t.depth_rate_m_s > 0.1);
  // The full dynamics at rest in a glide must satisfy the equilibrium
  // equations (000 eqs. 4-5) that the steady solver solves.
  const SteadyGlideResult steady = steady_glide_for_path(v.hydro, Environment{},
                                                         -t.glide_path_rad * 180.0 / M_PI, t.net_buoyancy_kg);
  CHECK_TRUE(steady.glide.has_value());
  DOUBLES_EQUAL(steady.glide->alpha_rad, t.alpha_rad, 1e-5);
  DOUBLES_EQUAL(steady.glide->speed_m_s, t.speed_m_s, 1e-5);
  DOUBLES_EQUAL(steady.glide->depth_rate_m_s, t.depth_rate_m_s, 1e-5);
  DOUBLES_EQUAL(0.0, t.pitch_rate_rad_s, 1e-7);
}

TEST(Dynamics, StepSizeIsWellInsideRk4Limits) {
  // The justification of GliderSimulator::kDefaultStepS, checked: the
  // linearized glide is stable and |lambda| h stays small for all modes.
  for (double pumped : {-250e-6, 250e-6}) {
    GliderSimulator sim = steady_dive(v, pumped, 0.0);
    const MassInputs m{pumped, 0.0, 0.0};
    const Eigen::EigenSolver<Eigen::Matrix<double, 5, 5>> solver(jacobian(sim.dynamics(), sim.state(), m));
    for (int i = 0; i < 5; ++i) {
      const std::complex<double> lambda = solver.eigenvalues()[i];
      CHECK(lambda.real() < 1e-9);  // a steady glide is (at worst neutrally) stable
      CHECK(std::abs(lambda) * GliderSimulator::kDefaultStepS < 0.35);
    }
  }
}

TEST(Dynamics, HalvingTheStepChangesLittle) {
  auto fly = [this](double step) {
    GliderSimulator sim(v, Environment{}, step);
    sim.reset_at_depth(100.0, 0.0, 0.0);
    sim.command_pumped_volume_m3(-250e-6);
    sim.command_battery_pos_m(0.005);
    sim.advance(300.0);
    return sim.state();
  };
  const State coarse = fly(GliderSimulator::kDefaultStepS);
  const State fine = fly(GliderSimulator::kDefaultStepS / 2.0);
  DOUBLES_EQUAL(fine[kZ], coarse[kZ], 1e-4);
  DOUBLES_EQUAL(fine[kTheta], coarse[kTheta], 1e-6);
}

TEST(Dynamics, BatteryForwardPitchesDown) {
  GliderSimulator aft = steady_dive(v, -250e-6, -0.0127);
  GliderSimulator fwd = steady_dive(v, -250e-6, 0.0127);
  CHECK(fwd.truth().pitch_rad < aft.truth().pitch_rad - 0.2);
}
