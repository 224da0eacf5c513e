// SPDX-License-Identifier: Apache-2.0
// The deployment view's intervals and a bias every segment shares (issue 26):
// a diagnosis that flies the Reynolds prior widens each segment's interval by
// the shift of a refit with the exponent one prior sigma higher - one exponent
// for the whole glider, so the same bias in every segment. The deployment's
// levels (the constant, a line's start, a hinge's level and end) are built
// from the scatter between segments, which cannot hold it: they carry it as a
// common-mode term. Slopes and steps are differences between segments, where
// it cancels: unchanged.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "glider/diagnose/deployment_diagnosis.hpp"
#include "glider/fitting_core/intervals.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/slocum/log_loader.hpp"

namespace diagnose = glider::diagnose;

namespace {

constexpr double kDay = 86400.0;

double half(const diagnose::Interval& i) { return 0.5 * (i.high - i.low); }

void check_same(const diagnose::Interval& a, const diagnose::Interval& b, const char* what) {
  char text[160];
  std::snprintf(text, sizeof text, "%s: %.9g [%.9g, %.9g] against %.9g [%.9g, %.9g]", what, a.value, a.low, a.high,
                b.value, b.low, b.high);
  CHECK_TEXT(a.value == b.value && a.low == b.low && a.high == b.high, text);
}

// The level's interval: the scatter's half-width and 1.96 |its shift| in quadrature.
void check_widened(const diagnose::Interval& plain, const diagnose::Interval& shared, const diagnose::SharedBias& bias,
                   double level_shift, const char* what) {
  char text[200];
  std::snprintf(text, sizeof text, "%s: half-width %.6g -> %.6g, shared sigma %.6g (shift %.6g)", what, half(plain),
                half(shared), bias.sigma, level_shift);
  UT_PRINT(text);
  DOUBLES_EQUAL(plain.value, shared.value, 0.0);
  DOUBLES_EQUAL(std::abs(level_shift), bias.sigma, 1e-12 * (1.0 + std::abs(level_shift)));
  DOUBLES_EQUAL(half(plain), bias.between_half_width, 1e-12 * half(plain));
  DOUBLES_EQUAL(std::hypot(half(plain), glider::fitting_core::kZ95 * level_shift), half(shared), 1e-9 * half(shared));
  CHECK_TEXT(half(shared) > half(plain), text);
}

}  // namespace

TEST_GROUP(DiagnoseDeploymentSharedBias){};

// A line over 10 segments (a hinge and a step fitted too) with a shift every
// segment shares (the same -0.015 in each, as comet-2016's drag): each level
// widens by exactly the shift, the slopes and the step's change do not move.
TEST(DiagnoseDeploymentSharedBias, LevelsCarryTheSharedShiftSlopesAndStepsDoNot) {
  std::vector<double> t, v, shift;
  const double wobble[] = {0.004, -0.006, 0.002, 0.005, -0.003, -0.004, 0.006, -0.002, 0.001, -0.003};
  for (int i = 0; i < 10; ++i) {
    t.push_back(1.5e9 + i * kDay);
    v.push_back(1.2 + 0.01 * i + wobble[i]);
    shift.push_back(-0.015 + 0.0005 * i);  // the speeds flown differ a little from segment to segment
  }
  const diagnose::Trend plain = diagnose::fit_trend(t, v);
  const diagnose::Trend shared = diagnose::fit_trend(t, v, {}, shift);
  STRCMP_EQUAL(to_string(plain.shape), to_string(shared.shape));
  UT_PRINT(shared.describe("ratio").c_str());

  double mean_shift = 0.0;
  for (double x : shift) mean_shift += x / static_cast<double>(shift.size());
  check_widened(plain.mean, shared.mean, shared.mean_shared, mean_shift, "constant");
  // The line's start: the same least squares on the shifts.
  const diagnose::Trend of_shifts = diagnose::fit_trend(t, shift);
  check_widened(plain.at_start, shared.at_start, shared.at_start_shared, of_shifts.at_start.value, "line's start");
  CHECK(shared.hinge_level_shared.sigma > 0.0 && shared.hinge_end_shared.sigma > 0.0);
  CHECK(half(shared.hinge_level) > half(plain.hinge_level) && half(shared.hinge_end) > half(plain.hinge_end));

  check_same(plain.slope_per_day, shared.slope_per_day, "slope");
  check_same(plain.step_change, shared.step_change, "step");
  check_same(plain.hinge_slope_per_day, shared.hinge_slope_per_day, "hinge slope");
  DOUBLES_EQUAL(plain.p_slope, shared.p_slope, 0.0);

  // No shift (an exponent asked for or stated): nothing moves.
  const diagnose::Trend none = diagnose::fit_trend(t, v, {}, std::vector<double>(10, 0.0));
  check_same(plain.mean, none.mean, "constant without a shift");
  DOUBLES_EQUAL(0.0, none.mean_shared.sigma, 0.0);
}

// comet-2016's real segments (the four of its ten binaries with steady dives
// in two yos or more; tests/data/real/dbd/comet-2016) against the silent
// slocum_shallow.toml: the diagnosis flies the prior 0.1 and its sigma. The
// same deployment with the exponent asked for (0.1: the same flight, no prior
// sigma) gives the scatter alone: the values are the same, the drag's
// constant widens by its segments' mean shift, its slope and step do not.
TEST(DiagnoseDeploymentSharedBias, Comet2016ConstantCarriesTheReynoldsPriorsShift) {
  const std::string dir = GLIDER_SOURCE_DIR "/tests/data/real/dbd/comet-2016/comet-2016-174-05-";
  std::vector<diagnose::SegmentInput> segments;
  for (const char* n : {"001", "002", "004", "006"}) {
    diagnose::SegmentInput& in = segments.emplace_back();
    in.name = n;
    const glider::flightlog::FlightLog log =
        glider::slocum::load_flight_log({{dir + n + ".dbd", dir + n + ".ebd"}, {}}, {});
    in.observations = diagnose::prepare_observations(log);
  }
  const glider::model::VehicleParams shallow =
      glider::model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_shallow.toml");
  diagnose::DeploymentOptions options;
  options.diagnose.model = diagnose::FlightModelKind::kSteady;  // the intervals, not the model, are under test
  options.effects = {diagnose::Effect::kDragChange, diagnose::Effect::kBuoyancyOffset};
  const diagnose::DeploymentDiagnosis prior = diagnose::diagnose_deployment(shallow, segments, options);
  options.diagnose.drag_reynolds_exponent = diagnose::kDragReynoldsExponentPrior;
  const diagnose::DeploymentDiagnosis asked = diagnose::diagnose_deployment(shallow, segments, options);
  LONGS_EQUAL(4, prior.diagnosed);
  LONGS_EQUAL(4, asked.diagnosed);

  const diagnose::EffectHistory& drag = prior.effects.at(0);
  const diagnose::EffectHistory& drag_asked = asked.effects.at(0);
  CHECK(drag.effect == diagnose::Effect::kDragChange);
  double mean_shift = 0.0;
  for (std::size_t i = 0; i < drag.value.size(); ++i) {
    DOUBLES_EQUAL(drag_asked.value[i], drag.value[i], 1e-12);
    DOUBLES_EQUAL(0.0, drag_asked.reynolds_prior_shift[i], 0.0);  // asked: no prior sigma
    // A higher exponent lowers the factor that holds at the reference speed
    // for a glider flying below it (comet: about 1.1 % per 0.05).
    CHECK(drag.reynolds_prior_shift[i] < -0.005);
    mean_shift += drag.reynolds_prior_shift[i] / 4.0;
  }
  UT_PRINT(("prior: " + drag.trend.describe("ratio")).c_str());
  UT_PRINT(("asked: " + drag_asked.trend.describe("ratio")).c_str());
  check_widened(drag_asked.trend.mean, drag.trend.mean, drag.trend.mean_shared, mean_shift, "comet-2016 drag");
  check_same(drag_asked.trend.slope_per_day, drag.trend.slope_per_day, "comet-2016 drag slope");
  check_same(drag_asked.trend.step_change, drag.trend.step_change, "comet-2016 drag step");
}
