// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/effective_samples.hpp"

#include <algorithm>

namespace glider::fitting_core {

double effective_sample_count(std::span<const double> x, double mean) {
  double var = 0.0, lag1 = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    var += (x[i] - mean) * (x[i] - mean);
    if (i > 0) lag1 += (x[i] - mean) * (x[i - 1] - mean);
  }
  const double rho1 = var > 0.0 ? std::clamp(lag1 / var, 0.0, 0.99) : 0.0;
  return static_cast<double>(x.size()) * (1.0 - rho1) / (1.0 + rho1);
}

}  // namespace glider::fitting_core
