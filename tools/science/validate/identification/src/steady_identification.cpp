// SPDX-License-Identifier: Apache-2.0
#include "glider/identification/steady_identification.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <optional>

#include "offset_solver.hpp"
#include "propagation.hpp"

namespace glider::identification {

SteadyIdentification identify_steady_glides(const model::VehicleParams& vehicle, const LiftModel& lift,
                                            std::span<const SteadyGlideSample> samples,
                                            const BuoyancyOffsetOptions& options) {
  SteadyIdentification id;
  id.buoyancy = estimate_buoyancy_offset(lift, samples, options);
  if (!id.buoyancy.ok) return id;
  const double offset_kg = id.buoyancy.offset_kg;
  id.drag = estimate_drag_polar(lift, samples, offset_kg);
  id.pitch = estimate_pitch_trim(vehicle, lift, samples, offset_kg);
  if (!id.drag.ok || !id.pitch.ok) return id;

  // drag and pitch results (cd0, cd_alpha2, pitch trim, cm totals) at a given offset
  auto downstream = [&](std::span<const SteadyGlideSample> s, double offset) -> std::optional<Eigen::VectorXd> {
    const DragPolarFit drag = estimate_drag_polar(lift, s, offset);
    const PitchTrimEstimate pitch = estimate_pitch_trim(vehicle, lift, s, offset);
    if (!drag.ok || !pitch.ok) return std::nullopt;
    Eigen::VectorXd r(5);
    r << drag.cd0, drag.cd_alpha2_per_rad2, pitch.pitch_trim_offset_m, pitch.cm_alpha_total_m, pitch.cm_alpha_viscous_m;
    return r;
  };
  Eigen::VectorXd se = detail::propagate_sample_errors(
      samples, options.input_sd, 5, [&](std::span<const SteadyGlideSample> s) -> std::optional<Eigen::VectorXd> {
        const auto offset = detail::solve_offset(lift, s, options, offset_kg);
        if (!offset) return std::nullopt;
        return downstream(s, *offset);
      });
  const double excess_kg = std::sqrt(std::max(0.0, id.buoyancy.uncertainty_kg * id.buoyancy.uncertainty_kg -
                                                       id.buoyancy.input_se_kg * id.buoyancy.input_se_kg));
  if (excess_kg > 0.0) {
    const auto plus = downstream(samples, offset_kg + excess_kg);
    const auto minus = downstream(samples, offset_kg - excess_kg);
    if (plus && minus) se = (se.cwiseAbs2() + (0.5 * (*plus - *minus)).cwiseAbs2()).cwiseSqrt();
  }
  id.drag.cd0_input_se = se[0];
  id.drag.cd_alpha2_input_se_per_rad2 = se[1];
  id.pitch.pitch_trim_offset_input_se_m = se[2];
  id.pitch.cm_alpha_total_input_se_m = se[3];
  id.pitch.cm_alpha_viscous_input_se_m = se[4];
  return id;
}

}  // namespace glider::identification
