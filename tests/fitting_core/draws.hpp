// SPDX-License-Identifier: Apache-2.0
#pragma once
// Seeded normal draws for the fitting core's tests, the same on every platform.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace fitting_core_test {

inline double normal(std::mt19937_64& rng) {
  const double u1 = (static_cast<double>(rng() >> 11) + 0.5) / 9007199254740992.0;
  const double u2 = static_cast<double>(rng() >> 11) / 9007199254740992.0;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// An AR(1) series x_i = phi x_{i-1} + e_i, of stationary standard deviation sigma.
inline std::vector<double> ar1(std::mt19937_64& rng, std::size_t n, double phi, double sigma) {
  std::vector<double> x(n);
  const double innovation = sigma * std::sqrt(1.0 - phi * phi);
  double previous = sigma * normal(rng);
  for (double& v : x) {
    v = phi * previous + innovation * normal(rng);
    previous = v;
  }
  return x;
}

}  // namespace fitting_core_test
