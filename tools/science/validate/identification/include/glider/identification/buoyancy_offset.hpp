// SPDX-License-Identifier: Apache-2.0
#pragma once
// Paper 000 sec. 3.2: the buoyancy trim offset Delta m0 (the vehicle's net
// weight at zero ballast; - = light) from steady glides up and down.
//
// Why it is identifiable: lift is odd and drag even in the angle of attack
// (the hull is symmetric top to bottom), so the steady polar is symmetric and
// glides at equal |pitch| up and down fly at equal |a|. Reading the glides
// through the lift equation with the wrong net buoyancy breaks that symmetry
// (too heavy an assumed vehicle gives the dives a larger |a| than the climbs).
//
// Exact criterion used here, for any number of glides at unequal pitches: for
// a trial offset D every glide is read through the lift equation with
// m0 = ballast + D, and the |a| are fitted by linear least squares as
//   |a_i| = c0 + trend(u_i) + delta * d_i,   u_i = |theta_i| - mean |theta|,
//   d_i = +1/2 for a dive, -1/2 for a climb,  trend = c1 u (+ c2 u^2),
// so delta is how much larger |a| is going down than up at equal |pitch|. The
// offset is the root of delta(D) = 0 (delta rises monotonically with D). With
// one dive and one climb at the same |pitch| this is exactly the paper's
// "equal |a| at equal |theta|"; with two dives bracketing one climb and a
// fitted linear trend it interpolates the dives to the climb's pitch.
//
// The trend carries how |a| changes with |pitch| along the polar. It is either
// fitted (needs glides of some direction spread in pitch), or given as a
// slope d|a|/d|theta| (e.g. polar_alpha_per_pitch from a prior drag polar):
// needed when each direction was flown at one pitch only, where a fitted
// slope is confounded with delta.
//
// Note: at exactly equal |pitch| equal |a| means an equal glide path, and the
// lift equation then leaves m0 / zdot^2 equal up and down, so
//   D = (|m_b,climb| zdot_dive^2 - m_b,dive zdot_climb^2) / (zdot_dive^2 + zdot_climb^2),
// independent of C_L and rho A: the lift curve matters only through the
// correction for unequal pitches.
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "glider/identification/lift_glide.hpp"

namespace glider::identification {

struct BuoyancyOffsetOptions {
  int trend_degree = 1;                   // fitted trend terms: 0 (none), 1 (linear) or 2 (quadratic)
  std::optional<double> alpha_per_pitch;  // a given d|a|/d|theta| instead of a fitted trend
  SampleUncertainty input_sd;             // propagated into input_se_kg
  double search_min_kg = -1.0;            // offsets searched (further limited to those that keep every
  double search_max_kg = 1.0;             //   dive heavy and every climb light)
};

struct PairOffset {
  int dive = 0;  // indices into the samples
  int climb = 0;
  double offset_kg = 0.0;  // the offset that makes this pair symmetric alone (NaN: none)
};

struct BuoyancyOffsetEstimate {
  bool ok = false;
  std::string error;
  double offset_kg = 0.0;
  // Standard error from the scatter of |a| about the symmetric fit:
  // se(delta) / |d delta / d D| (NaN without degrees of freedom).
  double residual_se_kg = 0.0;
  // From options.input_sd, propagated through the whole estimate by central
  // differences, the samples' errors taken as independent (0 if none given).
  double input_se_kg = 0.0;
  // The larger of the two (not their sum: the scatter already contains the
  // measurement noise).
  double uncertainty_kg = 0.0;
  double alpha_per_pitch = 0.0;  // slope of the |a| trend at the mean |pitch| (given or fitted)
  int dives = 0;
  int climbs = 0;
  int dof = 0;  // of the symmetric fit
  // Every dive against every climb, |pitch| difference corrected with
  // alpha_per_pitch: how consistent the glides are with each other.
  std::vector<PairOffset> pairs;
  std::vector<GlideFromLift> glides;  // the samples read with offset_kg
};

BuoyancyOffsetEstimate estimate_buoyancy_offset(const LiftModel& lift, std::span<const SteadyGlideSample> samples,
                                                const BuoyancyOffsetOptions& options = {});

// d|a|/d|theta| along the steady polar of `prior` (its lift and drag) at the
// given |pitch|, for the correction of unequal pitches (NaN if no steady glide
// exists there). Symmetric: the same for dives and climbs.
double polar_alpha_per_pitch(const model::Hydrodynamics& prior, double abs_pitch_rad);

}  // namespace glider::identification
