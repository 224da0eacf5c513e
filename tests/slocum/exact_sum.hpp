// SPDX-License-Identifier: Apache-2.0
#pragma once
// Correctly rounded sum of doubles (Shewchuk's exact partials, the algorithm
// of Python's math.fsum), to compare sums bit for bit with reference.json.
#include <cmath>
#include <vector>

namespace glider::slocum::test {

inline double exact_sum(const std::vector<double>& values) {
  std::vector<double> partials;
  for (double x : values) {
    std::size_t kept = 0;
    for (double y : partials) {
      if (std::fabs(x) < std::fabs(y)) std::swap(x, y);
      const double high = x + y;
      const double low = y - (high - x);
      if (low != 0.0) partials[kept++] = low;
      x = high;
    }
    partials.resize(kept);
    partials.push_back(x);
  }
  // Round the partials' sum once, correctly (half-even on exact ties), as fsum does.
  double high = 0.0;
  if (!partials.empty()) {
    std::size_t n = partials.size();
    high = partials[--n];
    double low = 0.0;
    while (n > 0) {
      const double x = high;
      const double y = partials[--n];
      high = x + y;
      const double yr = high - x;
      low = y - yr;
      if (low != 0.0) break;
    }
    if (n > 0 && ((low < 0.0 && partials[n - 1] < 0.0) || (low > 0.0 && partials[n - 1] > 0.0))) {
      const double y = low * 2.0;
      const double x = high + y;
      const double yr = x - high;
      if (y == yr) high = x;
    }
  }
  return high;
}

}  // namespace glider::slocum::test
