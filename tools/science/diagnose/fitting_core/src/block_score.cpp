// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/block_score.hpp"

#include <cmath>
#include <cstddef>
#include <limits>

namespace glider::fitting_core {

double block_rms(std::span<const double> time_s, std::span<const long> cluster, std::span<const double> residual,
                 double block_s) {
  if (residual.empty()) return std::numeric_limits<double>::quiet_NaN();
  double weighted = 0.0;  // sum_b n_b mean_b^2 = sum_b (sum of the block)^2 / n_b
  double sum = 0.0, count = 0.0, start = 0.0;
  auto close = [&] {
    if (count > 0.0) weighted += sum * sum / count;
    sum = count = 0.0;
  };
  for (std::size_t i = 0; i < residual.size(); ++i) {
    const bool new_block = i == 0 || cluster[i] != cluster[i - 1] || block_s <= 0.0 || !(time_s[i] - start < block_s);
    if (new_block) {
      close();
      start = time_s[i];
    }
    sum += residual[i];
    count += 1.0;
  }
  close();
  return std::sqrt(weighted / static_cast<double>(residual.size()));
}

}  // namespace glider::fitting_core
