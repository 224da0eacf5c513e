// SPDX-License-Identifier: Apache-2.0
// The selection's rules at their edges: both margins and the BIC must agree,
// the same margins decide that two readings cannot be told apart.
#include <CppUTest/TestHarness.h>

#include <cmath>

#include "glider/fitting_core/selection.hpp"

namespace fc = glider::fitting_core;

TEST_GROUP(FittingCoreSelection){};

TEST(FittingCoreSelection, BothMarginsAndTheBicMustAgree) {
  const fc::Margins m{0.03, 0.0005};
  const fc::Score without{0.0100, 100.0};
  CHECK(fc::beats({0.0090, 90.0}, without, m));    // 10 % and 1 mm/s better, BIC lower
  CHECK(!fc::beats({0.0098, 90.0}, without, m));   // 2 %: under the relative margin
  CHECK(!fc::beats({0.0090, 101.0}, without, m));  // the BIC disagrees
  const fc::Score small{0.0010, 100.0};
  CHECK(!fc::beats({0.0008, 90.0}, small, m));  // 20 % but 0.2 mm/s: under the absolute margin
  CHECK(fc::improves_heldout(0.0090, 0.0100, m));
  CHECK(!fc::improves_heldout(0.0100, 0.0100, m));
}

TEST(FittingCoreSelection, TheMarginIsTheLargerOfTheTwo) {
  DOUBLES_EQUAL(0.0005, fc::margin(0.010, {0.03, 0.0005}), 1e-15);
  DOUBLES_EQUAL(0.0015, fc::margin(0.050, {0.03, 0.0005}), 1e-15);
}

TEST(FittingCoreSelection, WithinAMarginTheHeldOutYosCannotTellThemApart) {
  const fc::Margins m{0.03, 0.0005};
  CHECK(fc::indistinguishable(0.0104, 0.0100, m));   // 0.4 mm/s worse: within 0.5
  CHECK(fc::indistinguishable(0.0090, 0.0100, m));   // better: certainly not worse
  CHECK(!fc::indistinguishable(0.0106, 0.0100, m));  // 0.6 mm/s worse
}

// comet-2016 with --score-block 60: a uniform water velocity chosen, the
// buoyancy offset in its place 1.9 % worse on the held-out samples (within
// the margins) but beyond them on the glide-averaged score. The verdict was
// "told apart" on the score alone; the samples cannot tell them apart.
TEST(FittingCoreSelection, TwoFitsAreToldApartOnlyWhenBothViewsAgree) {
  const fc::Margins m{0.03, 0.0005};
  const fc::HeldOut chosen{0.0060, 0.011508};
  CHECK(fc::indistinguishable(fc::HeldOut{0.0070, 0.011724}, chosen, m));          // score apart, samples not
  CHECK(fc::indistinguishable(fc::HeldOut{0.0062, 0.0130}, chosen, m));            // samples apart, score not
  CHECK(!fc::indistinguishable(fc::HeldOut{0.0070, 0.0130}, chosen, m));           // both apart
  CHECK(fc::indistinguishable(fc::HeldOut{0.0104, 0.0104}, {0.0100, 0.0100}, m));  // no blocks: the plain rule
  CHECK(!fc::indistinguishable(fc::HeldOut{0.0106, 0.0106}, {0.0100, 0.0100}, m));
}

TEST(FittingCoreSelection, BayesianInformationCriterion) {
  DOUBLES_EQUAL(100.0 * std::log(2.0 / 100.0) + 3.0 * std::log(100.0), fc::bic(2.0, 100.0, 3.0), 1e-12);
}
