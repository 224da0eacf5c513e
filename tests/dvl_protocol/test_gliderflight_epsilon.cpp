// SPDX-License-Identifier: Apache-2.0
// gliderflight's calibration with its hull compressibility as a third
// parameter (the DVL protocol gives gliderflight what glider-diagnose may
// fit): on a log flown by its own steady model with a known epsilon, the
// three-parameter fit finds the three, and the example's two-parameter fit
// (epsilon held at 5e-10) cannot fit the depth rate as well.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <vector>

#include "glider/science/gliderflight_model.hpp"

using namespace glider::science;

namespace {

// Three yos between about 30 and 69 m (3-7 bar), 1 s records, each record's
// pressure the one the model's own vertical velocity gives (a fixed point:
// the buoyancy depends on the pressure it produces).
GliderflightInput flown_by(const GliderflightParameters& truth) {
  GliderflightInput in;
  for (int k = 0; k < 1800; ++k) {
    const bool dive = (k / 300) % 2 == 0;
    in.time_s.push_back(k);
    in.pitch_rad.push_back(dive ? -0.4 : 0.4);
    in.buoyancy_change_cc.push_back(dive ? -200.0 : 200.0);
    in.density_kg_m3.push_back(1004.0);
    in.pressure_bar.push_back(4.5);
  }
  for (int pass = 0; pass < 20; ++pass) {
    const GliderflightResult r = gliderflight_solve(GliderflightKind::kSteady, truth, in);
    double height_m = -30.0;  // w is + up
    for (std::size_t i = 0; i < in.time_s.size(); ++i) {
      in.pressure_bar[i] = -height_m * truth.rho0_kg_m3 * 9.81 / 1e5;
      height_m += r.w_m_s[i];
    }
  }
  return in;
}

}  // namespace

TEST_GROUP(GliderflightEpsilon){};

TEST(GliderflightEpsilon, ThreeParameterFitFindsAKnownCompressibility) {
  GliderflightParameters truth;
  truth.cd0 = 0.16;
  truth.mass_kg = 69.95;  // heavy on the dives, light on the climbs at 1004 kg/m^3
  truth.epsilon_per_pa = 1.2e-9;
  const GliderflightInput in = flown_by(truth);
  std::vector<bool> fit(in.time_s.size(), true);
  for (std::size_t i = 0; i < fit.size(); ++i) fit[i] = i % 300 >= 20 && i % 300 < 280;  // not the turns
  double rms2 = 0.0, rms3 = 0.0;
  const GliderflightParameters two =
      gliderflight_calibrate(GliderflightKind::kSteady, {}, in, fit, &rms2, GliderflightFit::kCd0Mass);
  const GliderflightParameters three =
      gliderflight_calibrate(GliderflightKind::kSteady, {}, in, fit, &rms3, GliderflightFit::kCd0MassEpsilon);
  DOUBLES_EQUAL(5e-10, two.epsilon_per_pa, 0.0);  // the example's two leave epsilon alone
  DOUBLES_EQUAL(truth.epsilon_per_pa, three.epsilon_per_pa, 0.05e-9);
  DOUBLES_EQUAL(truth.cd0, three.cd0, 0.002);
  DOUBLES_EQUAL(truth.mass_kg, three.mass_kg, 0.005);
  CHECK(rms3 < 1e-4);        // the depth rate fitted (np.gradient of an Euler-integrated depth)
  CHECK(rms2 > 3.0 * rms3);  // the wrong epsilon shows in the depth rate
}
