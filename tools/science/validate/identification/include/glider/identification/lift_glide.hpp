// SPDX-License-Identifier: Apache-2.0
#pragma once
// Paper 000 sec. 3.1: a measured steady glide (pitch, depth rate, net
// buoyancy) read through a known lift curve. Eliminating the drag from the
// equilibrium equations (4)-(5) leaves the lift balance across the path,
//   1/2 rho A C_L(a) V^2 = m0 g cos(theta - a),   V = zdot / sin(a - theta)  (eq. 10),
// one equation in the angle of attack a. The drag then follows from the
// balance along the path (eqs. 11/12 combined): D = -m0 g sin(theta - a).
#include <optional>

#include "glider/identification/steady_sample.hpp"

namespace glider::identification {

struct GlideFromLift {
  double alpha_rad = 0.0;
  double speed_m_s = 0.0;
  double net_buoyancy_kg = 0.0;  // m0 = ballast + trim offset, + heavy
  double glide_path_rad = 0.0;   // theta - alpha, + climbing
  double lift_coefficient = 0.0;
  double drag_coefficient = 0.0;  // by the reference area, eqs. 11/12
};

// The glide with the given buoyancy trim offset (kg, added to the ballast).
// No value when the depth rate is zero, the net buoyancy points against the
// motion (a descending glide must be heavy), or the lift equation has no root
// with |a| inside the lift fit's range (hydro.fit_valid_to_rad): beyond it the
// identification would only read back the blend, not the vehicle.
std::optional<GlideFromLift> glide_from_lift(const LiftModel& lift, const SteadyGlideSample& sample,
                                             double buoyancy_offset_kg = 0.0);

}  // namespace glider::identification
