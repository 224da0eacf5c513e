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
#include "gliderflight_flown_log.hpp"

using namespace glider::science;

using glider::science::test::flown_by;

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
