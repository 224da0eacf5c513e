// SPDX-License-Identifier: Apache-2.0
#pragma once
// Paper 000 sec. 3.3: the steady pitching moment and the static pitch trim.
//
// In a steady glide (q = 0) the moment of the internal masses' weight about
// the CB balances the hydrodynamic moment, eq. (16):
//   1/2 rho A V^2 C_M(a) = (m_f3 - m_f1) v1 v3 + M_DL = -(gravity moment),
// so each glide gives C_M from the mass layout (model::VehicleParams) and
// its ballast and battery position. The moments come from
// model::GliderDynamics::evaluate at the steady state, not a second copy of
// eq. (3). C_M here is a length (moment / (q A)), the project's convention.
//
// The static pitch trim is not known exactly at sea: an error in the fixed
// masses' x position adds a constant moment ~ cos(theta). In the project's
// vocabulary it is the pitch_trim_offset: the battery-position error that
// explains it (the battery sits that far forward of where it is logged; + =
// nose heavy). Paper 000 finds it (as the offset mass position r_W1) by
// requiring C_M(a) to be odd: equal and opposite C_M for glides up and down
// at equal |pitch|. Generalised to any glides, C_M is fitted as
//   C_M,logged,i = cm_alpha a_i - pitch_trim_offset * w_i,   w_i = d C_M,i / d(battery position),
// a linear least-squares problem in (cm_alpha, pitch_trim_offset) with no
// intercept (paper 000: K_M0 = 0 by symmetry); for one symmetric pair it is
// exactly the paper's condition.
//
// What it cannot give: the vertical CG. Its moment ~ sin(theta) flips with
// the glide direction exactly as a moment odd in a does, so an error in z
// goes into cm_alpha (WE01 at 23-27 deg: 1.2-1.4 m/rad per mm of CG, against
// a total slope of 0.63): the paper, like this fit, takes r_W3 as known.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glider/identification/lift_glide.hpp"
#include "glider/model/dynamics.hpp"
#include "glider/units.hpp"

namespace glider::identification {

struct GlideMoment {
  GlideFromLift glide;
  double gravity_moment_nm = 0.0;       // internal masses' weight about the CB (+ nose up)
  double munk_moment_nm = 0.0;          // (m_f3 - m_f1) v1 v3
  double cm_total_m = 0.0;              // paper 000 eq. 16: Munk and viscous, = -gravity / (q A)
  double cm_viscous_m = 0.0;            // without Munk: the vehicle file's cm_alpha_m convention
  double cm_per_battery_m_per_m = 0.0;  // w: change of cm_total per metre of battery travel
};

struct PitchTrimOptions {
  // Propagated into the *_input_se values by central differences, every
  // sample's inputs and the buoyancy offset taken as independent. The moment
  // is a small difference of large ones (the ballast and battery give tens of
  // N m, the hydrodynamic moment ~0.1 N m), so a millimetre of battery
  // position matters: give the logging resolution at least.
  SampleUncertainty input_sd;
  double buoyancy_offset_sd_kg = 0.0;
};

struct PitchTrimEstimate {
  bool ok = false;
  std::string error;
  double pitch_trim_offset_m = 0.0;  // battery-position equivalent, + = nose heavy
  double pitch_trim_offset_se_m = 0.0;
  // Paper 000's r_W1 that gives the same moment: the vehicle's offset-mass x
  // moved by pitch_trim_offset * m_battery / m_w.
  double offset_mass_x_m = 0.0;
  double cm_alpha_total_m = 0.0;  // paper 000's C_M = K a (0.63 for WE01), Munk included
  double cm_alpha_total_se_m = 0.0;
  double cm_alpha_viscous_m = 0.0;  // the same fit without Munk (VehicleParams::hydro.cm_alpha_m)
  double cm_alpha_viscous_se_m = 0.0;
  double residual_sd_m = 0.0;  // of the total C_M about its fit
  int dof = 0;
  // From PitchTrimOptions (0 if none given); the *_se values above are the
  // fit's own (NaN without degrees of freedom).
  double pitch_trim_offset_input_se_m = 0.0;
  double cm_alpha_total_input_se_m = 0.0;
  double cm_alpha_viscous_input_se_m = 0.0;
  std::vector<GlideMoment> glides;

  double pitch_trim_offset_in() const { return m_to_in(pitch_trim_offset_m); }
};

// The moment terms of one glide (read with the buoyancy offset) on the given
// dynamics; its water must have the lift model's density. No value if the
// glide cannot be read (see glide_from_lift).
std::optional<GlideMoment> glide_moment(const model::GliderDynamics& dynamics, const LiftModel& lift,
                                        const SteadyGlideSample& sample, double buoyancy_offset_kg);

// Needs glides both up and down (else pitch trim and cm_alpha are confounded).
PitchTrimEstimate estimate_pitch_trim(const model::VehicleParams& vehicle, const LiftModel& lift,
                                      std::span<const SteadyGlideSample> samples, double buoyancy_offset_kg,
                                      const PitchTrimOptions& options = {});

}  // namespace glider::identification
