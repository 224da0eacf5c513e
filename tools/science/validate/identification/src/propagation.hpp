// SPDX-License-Identifier: Apache-2.0
#pragma once
// Central-difference propagation of independent input errors (one standard
// deviation per input, the same for every sample) through an estimator:
//   var(result_k) = sum over samples and inputs of (d result_k / d input * sd)^2.
// Private to the library.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "glider/identification/steady_sample.hpp"

namespace glider::identification::detail {

// `estimate(samples)` returns the results (always `count` of them) or
// nothing; if any perturbed estimate fails, every standard error is NaN.
template <typename Estimate>
Eigen::VectorXd propagate_sample_errors(std::span<const SteadyGlideSample> samples, const SampleUncertainty& sd,
                                        Eigen::Index count, Estimate&& estimate) {
  Eigen::VectorXd variance = Eigen::VectorXd::Zero(count);
  std::vector<SteadyGlideSample> perturbed(samples.begin(), samples.end());
  const std::array<std::pair<double SteadyGlideSample::*, double>, 4> inputs{{
      {&SteadyGlideSample::pitch_rad, sd.pitch_rad},
      {&SteadyGlideSample::depth_rate_m_s, sd.depth_rate_m_s},
      {&SteadyGlideSample::ballast_net_kg, sd.ballast_kg},
      {&SteadyGlideSample::battery_pos_m, sd.battery_pos_m},
  }};
  for (SteadyGlideSample& sample : perturbed) {
    for (const auto& [member, step] : inputs) {
      if (step <= 0.0) continue;
      const double original = sample.*member;
      sample.*member = original + step;
      const std::optional<Eigen::VectorXd> plus = estimate(std::span<const SteadyGlideSample>(perturbed));
      sample.*member = original - step;
      const std::optional<Eigen::VectorXd> minus = estimate(std::span<const SteadyGlideSample>(perturbed));
      sample.*member = original;
      if (!plus || !minus) return Eigen::VectorXd::Constant(count, std::numeric_limits<double>::quiet_NaN());
      variance += (0.5 * (*plus - *minus)).cwiseAbs2();
    }
  }
  return variance.cwiseSqrt();
}

}  // namespace glider::identification::detail
