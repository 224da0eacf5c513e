// SPDX-License-Identifier: Apache-2.0
#pragma once
// Is a measured speed through water (a DVL's) one this flight can have had?
// The speed is scored, never fitted; but the reference itself can be wrong
// (a water-track DVL measures against a layer metres ahead, and processing
// can fail for a dive). The check uses only kinematics: the measured depth
// rate w is the glider's own vertical speed through the water plus the
// water's, and the glider's own is its speed times the sine of its glide path
// angle. With the model's glide path (its through-water depth rate over its
// speed), a reference speed U implies the water's vertical velocity
//   w_water = w - U * (w_model_through_water / U_model).
// A model's glide path can be wrong for the whole log (a wrong lift slope:
// against WE01 every yo of gliderflight-adcp implies -67 mm/s), and that
// error is common to yos flown alike; a reference that fails for one yo is
// not. So each yo's mean is compared with the log's median over its yos:
// where it differs by more than the water's vertical velocity plausibly does
// (the vocabulary's bound for vertical_water_velocity, 2 cm/s), the measured
// speed does not belong to the measured depth rate and pitch: the yo's
// reference is inconsistent. The diagnosis reports the score with and
// without such yos, and names them; it never drops one silently.
//
// On gliderflight-adcp, yo 17: the DVL reads 0.195 m/s where the 17 dives
// before at the same pitch, ballast, density and depth rate read 0.288-0.304,
// with a normal DVL record (68 ensembles of 829 bytes every 3.2 s; the
// others 66-71) and nothing else different in the glider's own logs; the
// speed implies water sinking ~4 cm/s through the whole 30 m dive while the
// climb after it rose as fast as the others.
#include <span>
#include <vector>

#include "glider/diagnose/diagnose.hpp"

namespace glider::diagnose {

// The water's vertical velocity (m/s, + down) a reference speed implies at a
// sample; NaN when any input is not finite or the model's speed is ~0.
double implied_water_velocity(double measured_rate_m_s, double model_rate_through_water_m_s, double reference_speed_m_s,
                              double model_speed_m_s);

// Sets each yo's implied_water_w_m_s (the mean of `implied`, by `yo` of the
// samples, in by_yo's order) and reference_consistent (|mean - median| <=
// bound; a yo without a value stays consistent); returns the median over the
// yos (NaN if none).
double check_reference_by_yo(std::vector<SpeedOfYo>& by_yo, std::span<const double> implied, std::span<const int> yo,
                             double bound_m_s);

}  // namespace glider::diagnose
