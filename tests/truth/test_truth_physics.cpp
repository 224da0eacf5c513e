// SPDX-License-Identifier: Apache-2.0
// The truth simulator's own physics: its steady glide against the closed
// form of its own equations, energy conservation without hydrodynamics,
// its integrator's accuracy and convergence, its sensor noise's statistics.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <random>

#include "glider/truth/dormand_prince.hpp"
#include "glider/truth/dynamics.hpp"
#include "glider/truth/sensors.hpp"
#include "glider/truth/vehicle.hpp"
#include "glider/truth/water.hpp"

using namespace glider::truth;

namespace {

const std::string kShallow = std::string(GLIDER_SOURCE_DIR) + "/boards/vehicles/slocum_shallow.toml";
const std::string kDeep = std::string(GLIDER_SOURCE_DIR) + "/boards/vehicles/slocum_we01.toml";

Water still_uniform_water() {
  Water w;
  w.surface_temperature_c = w.deep_temperature_c = 10.0;
  w.surface_salinity = w.deep_salinity = 35.0;
  w.wave_w_m_s = 0.0;
  w.current_east_m_s = w.current_north_m_s = 0.0;
  w.shear_per_s = 0.0;
  w.compression_kg_m3_per_m = 0.0;
  return w;
}

State start(const Vehicle& v, double piston, double battery) {
  State y{};
  y[kDepth] = y[kSensedDepth] = 50.0;
  y[kPitch] = piston < 0.0 ? -0.4 : 0.4;
  y[kSurge] = 0.3;
  y[kRoll] = v.heading.roll_rad;
  y[kPiston] = y[kDisplaced] = piston;
  y[kBattery] = battery;
  return y;
}

// The closed-form steady glide of the truth's equations (q = 0, lift at
// its quasi-steady value): for an angle of attack a the glide is xi below
// the horizontal with tan xi = C_D / C_L and 1/2 rho V^2 S |C| = |net
// weight|; a is where the pitch moment (hydrodynamic, static at pitch
// a - xi, Munk) vanishes. Dives (heavy, a > 0) only.
struct SteadyGlide {
  double alpha, speed, pitch, depth_rate;
};

SteadyGlide closed_form(const Vehicle& v, double density, double net_n, double battery, double piston) {
  const Hydro& h = v.hydro;
  auto glide = [&](double a) {
    const double cl = h.cl0 + h.cl_alpha * a + h.cl_alpha_abs_alpha * a * std::abs(a);
    double speed = 0.3;
    double cd = 0.0;
    for (int i = 0; i < 100; ++i) {
      cd = h.cd0 * std::pow(speed / v.unmodelled.drag_reference_speed_m_s, -v.unmodelled.drag_reynolds_exponent) +
           h.cd_alpha2 * a * a;
      speed = std::sqrt(2.0 * net_n / (density * h.area_m2 * std::hypot(cl, cd)));
    }
    const double xi = std::atan2(cd, cl);
    SteadyGlide g{a, speed, a - xi, speed * std::sin(xi)};
    return g;
  };
  auto moment = [&](double a) {
    const SteadyGlide g = glide(a);
    const double m = v.mass_kg();
    const double xg = (v.offset_kg * v.offset_x_m + v.battery_kg * (v.battery_x_at_zero_m + battery)) / m;
    const double zg = (v.offset_kg * v.offset_z_m + v.battery_kg * v.battery_z_m) / m;
    const double dyn = 0.5 * density * g.speed * g.speed * h.area_m2;
    return dyn * (h.cm0_m + h.cm_alpha_m * a) - m * kGravity * (zg * std::sin(g.pitch) + xg * std::cos(g.pitch)) +
           density * kGravity * piston * v.ballast_x_m * std::cos(g.pitch) +
           (v.added_z_kg - v.added_x_kg) * g.speed * g.speed * std::cos(a) * std::sin(a);
  };
  double lo = 1e-4, hi = v.hydro.fit_valid_to_rad;
  CHECK(moment(lo) * moment(hi) < 0.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (moment(lo) * moment(mid) <= 0.0 ? hi : lo) = mid;
  }
  return glide(0.5 * (lo + hi));
}

void check_steady(const std::string& path, double battery_in) {
  Vehicle v = load_vehicle(path);
  v.hull_compressibility_per_pa = 0.0;  // else the weight drifts with depth: quasi-steady, not steady
  Water water = still_uniform_water();
  water.density_offset_kg_m3 = v.trim_density_kg_m3 - water.density_kg_m3(0.0, 0.0);  // trimmed for this water
  const double piston = v.ballast_min_m3 * 0.6, battery = battery_in * 0.0254;
  Dynamics dyn{v, water, {piston, battery, 0.0, 0.0}, 0.0, 1.0, 0.3, nullptr};
  State y = start(v, piston, battery);
  double t = 0.0, h = 0.1;
  IntegrationStats stats;
  integrate(dyn, t, y, 1500.0, h, StepControl{1e-9, 1e-11, 2.0, 1e-8}, stats);
  const Dynamics::Forces f = dyn.forces(t, y);
  const SteadyGlide g = closed_form(v, f.density_kg_m3, f.net_weight_n, battery, piston);
  DOUBLES_EQUAL(g.alpha, f.alpha_rad, 1e-5);
  DOUBLES_EQUAL(g.pitch, y[kPitch], 1e-5);
  DOUBLES_EQUAL(g.speed, f.speed_m_s, 1e-5 * g.speed);
  State d{};
  dyn(t, y, d);
  DOUBLES_EQUAL(g.depth_rate, d[kDepth], 1e-5 * g.depth_rate);
  DOUBLES_EQUAL(0.0, y[kPitchRate], 1e-8);
  // A sane glide for a Slocum: 15-45 deg below the horizontal, 0.1-0.6 m/s.
  CHECK(g.pitch < -0.2 && g.pitch > -0.9);
  CHECK(g.speed > 0.1 && g.speed < 0.6);
}

}  // namespace

TEST_GROUP(TruthSteadyGlide){};

TEST(TruthSteadyGlide, ShallowVariantSettlesOnItsClosedForm) { check_steady(kShallow, 0.75); }
TEST(TruthSteadyGlide, DeepVariantSettlesOnItsClosedForm) { check_steady(kDeep, 0.3); }

TEST_GROUP(TruthEnergy){};

// Without hydrodynamics, kinetic energy (with the added masses) plus the
// potential of the net weight and of the pitch pendulum is conserved: the
// rigid-body and added-mass Coriolis terms do no work, and the mass
// matrix, centre of gravity and static moment agree.
TEST(TruthEnergy, ConservedWithoutHydrodynamics) {
  Vehicle v = load_vehicle(kShallow);
  v.hydro = Hydro{};
  v.hydro.cn90 = 0.0;
  v.unmodelled.cl_q = 0.0;
  v.unmodelled.drag_reynolds_exponent = 0.0;
  v.hull_compressibility_per_pa = 0.0;
  const Water water = still_uniform_water();
  const double piston = -100e-6, battery = 0.01;
  Dynamics dyn{v, water, {piston, battery, 0.0, 0.0}, 0.0, 1.0, 0.3, nullptr};
  State y = start(v, piston, battery);
  y[kHeave] = 0.05;
  y[kPitchRate] = 0.1;
  const double m = v.mass_kg();
  const double xg = (v.offset_kg * v.offset_x_m + v.battery_kg * (v.battery_x_at_zero_m + battery)) / m;
  const double zg = (v.offset_kg * v.offset_z_m + v.battery_kg * v.battery_z_m) / m;
  auto energy = [&](double t, const State& s) {
    const double net = dyn.forces(t, s).net_weight_n;
    const double rho = water.density_kg_m3(s[kDepth], t);
    const double pendulum = m * kGravity * (-zg * std::cos(s[kPitch]) + xg * std::sin(s[kPitch])) -
                            rho * kGravity * piston * v.ballast_x_m * std::sin(s[kPitch]);
    return kinetic_energy(v, s) + pendulum - net * s[kDepth];
  };
  double t = 0.0, h = 0.01;
  const double e0 = energy(t, y);
  IntegrationStats stats;
  double worst = 0.0;
  for (int k = 1; k <= 60; ++k) {
    integrate(dyn, t, y, k * 1.0, h, StepControl{1e-11, 1e-13, 0.5, 1e-9}, stats);
    worst = std::max(worst, std::abs(energy(t, y) - e0));
  }
  CHECK(kinetic_energy(v, y) > 1.0);  // it moved: the check is not of a body at rest
  CHECK_TRUE(worst < 1e-7);
}

TEST_GROUP(TruthIntegrator){};

TEST(TruthIntegrator, ExponentialDecayWithinTolerance) {
  std::array<double, 1> y{1.0};
  double t = 0.0, h = 0.1;
  IntegrationStats stats;
  integrate([](double, const std::array<double, 1>& x, std::array<double, 1>& d) { d[0] = -x[0]; }, t, y, 5.0, h,
            StepControl{1e-10, 1e-12, 1.0, 1e-9}, stats);
  DOUBLES_EQUAL(std::exp(-5.0), y[0], 1e-10);
  DOUBLES_EQUAL(5.0, t, 0.0);
}

// Tighter tolerances converge on the same flight: the error of a 300 s
// transient from rest against a 1e-12 reference falls with the tolerance.
TEST(TruthIntegrator, ConvergesAsTheToleranceTightens) {
  const Vehicle v = load_vehicle(kShallow);
  Water water = still_uniform_water();
  water.wave_w_m_s = 0.005;
  const double piston = v.ballast_min_m3;
  Dynamics dyn{v, water, {piston, 0.0, 0.1, 0.0}, 0.0, 1.0, 0.3, nullptr};
  auto run = [&](double tolerance) {
    State y = start(v, 0.0, 0.0);
    y[kSurge] = 0.0;
    y[kPitch] = 0.0;
    double t = 0.0, h = 0.1;
    IntegrationStats stats;
    integrate(dyn, t, y, 300.0, h, StepControl{tolerance, tolerance * 1e-2, 2.0, 1e-9}, stats);
    return y;
  };
  const State reference = run(1e-12);
  double previous = 1e9;
  for (double tolerance : {1e-4, 1e-6, 1e-8}) {
    const State y = run(tolerance);
    const double error = std::abs(y[kDepth] - reference[kDepth]) + std::abs(y[kHeading] - reference[kHeading]);
    CHECK_TRUE(error < previous);
    previous = error;
  }
  CHECK_TRUE(previous < 1e-5);
}

TEST_GROUP(TruthSensors){};

// The AR(1) noise is stationary with its sigma and correlation at any
// sampling interval: sample statistics of 40,000 draws.
TEST(TruthSensors, Ar1HasItsSigmaAndCorrelation) {
  std::mt19937_64 rng(11);
  for (double dt : {1.0, 4.0}) {
    Ar1 noise(0.07, 2.7);
    std::vector<double> x;
    for (int i = 0; i < 40000; ++i) x.push_back(noise.next(dt, rng));
    double mean = 0.0, var = 0.0, lag = 0.0;
    for (double v : x) mean += v / x.size();
    for (double v : x) var += (v - mean) * (v - mean) / x.size();
    for (std::size_t i = 1; i < x.size(); ++i) lag += (x[i] - mean) * (x[i - 1] - mean) / (x.size() - 1);
    DOUBLES_EQUAL(0.07, std::sqrt(var), 0.07 * 0.03);
    DOUBLES_EQUAL(std::exp(-dt / 2.7), lag / var, 0.02);
  }
}

TEST(TruthSensors, QuantizesToItsStep) {
  const SensorNoise n = SensorNoise::slocum();
  const double q = quantize(0.123456, n.angle_step_rad);
  DOUBLES_EQUAL(0.0, std::remainder(q, n.angle_step_rad), 1e-12);
  DOUBLES_EQUAL(0.123456, q, n.angle_step_rad / 2.0);
  DOUBLES_EQUAL(12.35, quantize(12.34, n.depth_step_m), 1e-9);  // 0.025 m steps
}
