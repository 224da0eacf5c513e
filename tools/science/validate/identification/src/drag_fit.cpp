// SPDX-License-Identifier: Apache-2.0
#include "glider/identification/drag_fit.hpp"

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <vector>

#include "glider/identification/least_squares.hpp"
#include "propagation.hpp"

namespace glider::identification {

DragPolarFit fit_drag_polar(std::span<const GlideFromLift> glides) {
  DragPolarFit result;
  result.glides = static_cast<int>(glides.size());
  Eigen::MatrixXd design(glides.size(), 2);
  Eigen::VectorXd drag(glides.size());
  for (std::size_t i = 0; i < glides.size(); ++i) {
    const double a = glides[i].alpha_rad;
    design(static_cast<Eigen::Index>(i), 0) = 1.0;
    design(static_cast<Eigen::Index>(i), 1) = a * a;
    drag(static_cast<Eigen::Index>(i)) = glides[i].drag_coefficient;
  }
  const LinearFit fit = least_squares(design, drag);
  if (!fit.ok) return result;
  result.ok = true;
  result.cd0 = fit.coefficients[0];
  result.cd_alpha2_per_rad2 = fit.coefficients[1];
  result.cd0_se = fit.standard_errors[0];
  result.cd_alpha2_se_per_rad2 = fit.standard_errors[1];
  result.residual_sd = fit.residual_sd;
  return result;
}

namespace {

DragPolarFit read_and_fit(const LiftModel& lift, std::span<const SteadyGlideSample> samples, double offset_kg) {
  std::vector<GlideFromLift> glides;
  for (const SteadyGlideSample& s : samples) {
    const auto g = glide_from_lift(lift, s, offset_kg);
    if (!g) return {};
    glides.push_back(*g);
  }
  return fit_drag_polar(glides);
}

}  // namespace

DragPolarFit estimate_drag_polar(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                 double buoyancy_offset_kg, const DragPolarOptions& options) {
  DragPolarFit result = read_and_fit(lift, samples, buoyancy_offset_kg);
  if (!result.ok) return result;
  auto estimate = [&](std::span<const SteadyGlideSample> perturbed,
                      double offset_kg) -> std::optional<Eigen::VectorXd> {
    const DragPolarFit fit = read_and_fit(lift, perturbed, offset_kg);
    if (!fit.ok) return std::nullopt;
    return Eigen::Vector2d(fit.cd0, fit.cd_alpha2_per_rad2);
  };
  SampleUncertainty sd = options.input_sd;
  sd.battery_pos_m = 0.0;  // the battery does not enter the force balance
  Eigen::VectorXd se = detail::propagate_sample_errors(
      samples, sd, 2,
      [&](std::span<const SteadyGlideSample> perturbed) { return estimate(perturbed, buoyancy_offset_kg); });
  if (options.buoyancy_offset_sd_kg > 0.0) {
    const auto plus = estimate(samples, buoyancy_offset_kg + options.buoyancy_offset_sd_kg);
    const auto minus = estimate(samples, buoyancy_offset_kg - options.buoyancy_offset_sd_kg);
    se = (plus && minus) ? (se.cwiseAbs2() + (0.5 * (*plus - *minus)).cwiseAbs2()).cwiseSqrt().eval()
                         : Eigen::VectorXd::Constant(2, std::numeric_limits<double>::quiet_NaN());
  }
  result.cd0_input_se = se[0];
  result.cd_alpha2_input_se_per_rad2 = se[1];
  return result;
}

}  // namespace glider::identification
