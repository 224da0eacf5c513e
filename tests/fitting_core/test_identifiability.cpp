// SPDX-License-Identifier: Apache-2.0
// Signatures' correlation with the other findings' projected out: two
// effects that differ only by what a third explains are indistinguishable.
#include <CppUTest/TestHarness.h>

#include <Eigen/Dense>
#include <cmath>

#include "draws.hpp"
#include "glider/fitting_core/identifiability.hpp"

namespace fc = glider::fitting_core;

TEST_GROUP(FittingCoreIdentifiability) { std::mt19937_64 rng{20261129}; };

TEST(FittingCoreIdentifiability, CorrelationOfSignatures) {
  Eigen::VectorXd a(3), b(3), c(3);
  a << 1.0, 2.0, 3.0;
  b << -2.0, -4.0, -6.0;
  c << 3.0, 0.0, -1.0;  // orthogonal to a
  DOUBLES_EQUAL(1.0, fc::absolute_correlation(a, b), 1e-12);
  DOUBLES_EQUAL(0.0, fc::absolute_correlation(a, c), 1e-12);
  CHECK(std::isnan(fc::absolute_correlation(a, Eigen::VectorXd::Zero(3))));
}

TEST(FittingCoreIdentifiability, TheOtherFindingsAreProjectedOut) {
  const Eigen::Index n = 500;
  Eigen::VectorXd x(n), y(n), z(n), shared(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    x[i] = fitting_core_test::normal(rng);
    y[i] = x[i] + 0.1 * fitting_core_test::normal(rng);  // y is nearly x
    z[i] = fitting_core_test::normal(rng);               // z is not
    shared[i] = fitting_core_test::normal(rng);          // what another finding explains
  }
  Eigen::MatrixXd others(n, 1);
  others.col(0) = shared;
  const fc::Complement complement(others);
  DOUBLES_EQUAL(0.0, shared.dot(complement.of(x + 5.0 * shared)), 1e-9);
  // Alike once the other finding's part is gone, though raw they differ in sign:
  CHECK(fc::absolute_correlation(complement.of(x + 5.0 * shared), complement.of(y - 3.0 * shared)) > 0.99);
  // Alike raw only through the other finding's part: told apart once it is gone.
  CHECK(fc::absolute_correlation(x + 5.0 * shared, z + 5.0 * shared) > 0.9);
  CHECK(fc::absolute_correlation(complement.of(x + 5.0 * shared), complement.of(z + 5.0 * shared)) < 0.2);
  const fc::Complement none(Eigen::MatrixXd(n, 0));  // no other finding: unchanged
  DOUBLES_EQUAL(0.0, (none.of(x) - x).norm(), 1e-12);
}

TEST(FittingCoreIdentifiability, ThePairsToJudgeAreThoseThatLookAlike) {
  const Eigen::Index n = 400;
  std::vector<Eigen::VectorXd> columns(4, Eigen::VectorXd(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    columns[0][i] = fitting_core_test::normal(rng);                                // a finding
    columns[1][i] = fitting_core_test::normal(rng);                                // another finding
    columns[2][i] = -2.0 * columns[0][i] + 0.05 * fitting_core_test::normal(rng);  // looks like 0
    columns[3][i] = columns[1][i] + fitting_core_test::normal(rng);                // like 1 in part only
  }
  const auto signature = [&](int e) { return columns[static_cast<std::size_t>(e)]; };
  const std::vector<fc::ScreenedPair> pairs = fc::screen_pairs({0, 1}, {0, 1, 2, 3}, signature, 0.75);
  LONGS_EQUAL(1, pairs.size());  // 2 against 0; 3 correlates with 1 only ~0.7; chosen ones never
  LONGS_EQUAL(0, pairs[0].finding);
  LONGS_EQUAL(2, pairs[0].alternative);
  CHECK(pairs[0].correlation > 0.99);
  // A signature: the residuals' change per unit step, a sample that cannot be predicted changes nothing.
  const std::vector<double> base{1.0, 2.0, 3.0}, stepped{1.5, 2.0, std::nan("")};
  const Eigen::VectorXd s = fc::signature_column(stepped, base, 0.5);
  DOUBLES_EQUAL(1.0, s[0], 1e-12);
  DOUBLES_EQUAL(0.0, s[1], 1e-12);
  DOUBLES_EQUAL(0.0, s[2], 1e-12);
}
