// SPDX-License-Identifier: Apache-2.0
// The stalled steady glide at a prescribed pitch (stall_branch.hpp): where it
// appears, the dynamic model really has two glides, and which one it flies
// depends on where it starts.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "glider/diagnose/flight_model.hpp"
#include "glider/diagnose/stall_branch.hpp"
#include "glider/model/prescribed_pitch.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/units.hpp"

using namespace glider;

namespace {

model::VehicleParams we01() { return model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml"); }

diagnose::EffectValues lift(double factor) {
  diagnose::EffectValues x = diagnose::nominal_values();
  x[static_cast<std::size_t>(diagnose::Effect::kLiftChange)] = factor;
  return x;
}

// The angle of attack (deg) after ten minutes at a constant pitch (deg) and
// ballast, from a start at `alpha0_deg` and `speed0_m_s` (RK4, 0.5 s steps).
double settled_alpha_deg(const model::VehicleParams& v, double pitch_deg, double alpha0_deg, double speed0_m_s) {
  const model::PrescribedPitchDynamics dynamics(v);
  model::PrescribedPitchInputs in;
  in.theta_rad = pitch_deg * kRadPerDeg;
  in.pumped_volume_m3 = pitch_deg < 0.0 ? -2e-4 : 2e-4;  // 200 cc heavy diving, light climbing
  in.depth_m = 30.0;
  model::PrescribedPitchDynamics::Impulse p = dynamics.impulse(speed0_m_s * std::cos(alpha0_deg * kRadPerDeg),
                                                               speed0_m_s * std::sin(alpha0_deg * kRadPerDeg), in);
  constexpr double h = 0.5;
  for (double t = 0.0; t < 600.0; t += h) {
    const model::PrescribedPitchDynamics::Impulse k1 = dynamics.rate(p, in);
    const model::PrescribedPitchDynamics::Impulse k2 = dynamics.rate(p + 0.5 * h * k1, in);
    const model::PrescribedPitchDynamics::Impulse k3 = dynamics.rate(p + 0.5 * h * k2, in);
    const model::PrescribedPitchDynamics::Impulse k4 = dynamics.rate(p + h * k3, in);
    p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  const Eigen::Vector2d u = dynamics.velocities(p, in);
  return std::atan2(u[1], u[0]) / kRadPerDeg;
}

}  // namespace

TEST_GROUP(DiagnoseStallBranch){};

TEST(DiagnoseStallBranch, TheDynamicModelStaysStalledJustBelowTheOnsetAndLeavesJustAbove) {
  const model::VehicleParams nominal = we01();
  for (const double pitch_deg : {-26.0, 26.0}) {
    const double onset = diagnose::stall_onset_lift(nominal, lift(1.0), pitch_deg * kRadPerDeg);
    CHECK(onset > 0.5 && onset < 1.2);
    const double stalled_start = pitch_deg < 0.0 ? 15.0 : -15.0;
    // Below the onset a glide started stalled and slow (as leaving the
    // surface) stays so for ten minutes ...
    const double below =
        settled_alpha_deg(diagnose::apply(nominal, lift(onset - 0.01), NAN), pitch_deg, stalled_start, 0.15);
    CHECK(std::abs(below) > 10.0);
    // ... above it, it goes to the flight branch (a few degrees).
    const double above =
        settled_alpha_deg(diagnose::apply(nominal, lift(onset + 0.01), NAN), pitch_deg, stalled_start, 0.15);
    CHECK(std::abs(above) < 6.0);
    // And one started on the flight branch stays there: two glides.
    CHECK(std::abs(settled_alpha_deg(diagnose::apply(nominal, lift(onset - 0.01), NAN), pitch_deg, 0.2 * stalled_start,
                                     0.45)) < 6.0);
  }
}

TEST(DiagnoseStallBranch, SteeperGlidesStallAtLessLiftAndTheBandSpansTheGlidesPitches) {
  const model::VehicleParams nominal = we01();
  const double at24 = diagnose::stall_onset_lift(nominal, lift(1.0), -24.0 * kRadPerDeg);
  const double at28 = diagnose::stall_onset_lift(nominal, lift(1.0), -28.0 * kRadPerDeg);
  CHECK(at28 < at24);
  // Glides between 24 and 28 deg nose down (and an inflection's shallow
  // samples, outside the percentiles): the band runs between the two.
  std::vector<double> pitch;
  for (int k = 0; k <= 200; ++k) pitch.push_back((-24.0 - 4.0 * k / 200.0) * kRadPerDeg);
  pitch.push_back(-3.0 * kRadPerDeg);
  const diagnose::LiftBand band = diagnose::stall_onset_band(nominal, lift(1.0), pitch);
  CHECK(band.low >= at28 - 1e-3 && band.low < at28 + 0.01);
  CHECK(band.high <= at24 + 1e-3 && band.high > at24 - 0.01);
}
