// SPDX-License-Identifier: Apache-2.0
#pragma once
// The fits' cost bound, one rule for both planes: samples of a log are
// serially correlated, so an even stride loses little information.
#include <cstddef>
#include <utility>
#include <vector>

namespace glider::diagnose {

// Every k-th sample so that at most `max_samples` remain.
inline void thin(std::vector<std::size_t>& samples, std::size_t max_samples) {
  if (samples.size() <= max_samples) return;
  const std::size_t stride = (samples.size() + max_samples - 1) / max_samples;
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < samples.size(); k += stride) kept.push_back(samples[k]);
  samples = std::move(kept);
}

}  // namespace glider::diagnose
