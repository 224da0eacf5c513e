// SPDX-License-Identifier: Apache-2.0
#pragma once
// Selection of heading effects for one link of the loop: the nominal
// model's held-out error, each candidate fitted (Levenberg-Marquardt) on the
// fitted yos and scored on the held-out ones, forward selection while the
// held-out error drops by the margins and the BIC agrees, a backward check
// of the joint fit, 95 % intervals from the Jacobian with the noise counted
// over the effective number of independent samples.
#include <functional>
#include <span>
#include <vector>

#include "glider/diagnose/heading_effects.hpp"
#include "glider/fitting_core/intervals.hpp"
#include "glider/fitting_core/selection.hpp"

namespace glider::diagnose {

// Residuals (model - measured) at `samples` with these values (every effect
// not being fitted stays at its nominal value).
using HeadingResiduals =
    std::function<void(const HeadingValues& values, std::span<const std::size_t> samples, std::vector<double>& out)>;

struct HeadingFinding {
  HeadingEffect effect = HeadingEffect::kFinDelay;
  double value = 0.0, nominal = 0.0;
  double ci95_low = 0.0, ci95_high = 0.0;
  double heldout_rms = 0.0;  // with this and the stronger findings
  double gain = 0.0;         // fraction of the baseline held-out error removed so far
};

// A finding against an unused candidate of its link whose signature
// resembles it (fitting_core/identifiability.hpp, the vertical plane's rule):
// the candidate fitted in its place; ambiguous when it predicts the held-out
// yos within the selection's margins.
struct HeadingAmbiguity {
  HeadingEffect chosen = HeadingEffect::kFinDelay, alternative = HeadingEffect::kFinDelay;
  double correlation = 0.0;  // |correlation| of the signatures, the other findings' projected out
  double alternative_value = 0.0;
  double chosen_heldout_rms = 0.0, alternative_heldout_rms = 0.0;
  bool ambiguous = false;
  // Judged on the heading's held-out innovations (the yaw-lag probe's pair):
  // no signatures, so no correlation (NaN), and the held-out RMS are of the
  // innovations (rad), not of the rate error.
  bool on_innovations = false;
};

struct LinkFit {
  HeadingLink link = HeadingLink::kVehicle;
  std::vector<HeadingEffect> candidates;
  std::size_t samples = 0, train_samples = 0, heldout_samples = 0;
  double baseline_rms = 0.0, baseline_rms_dive = 0.0, baseline_rms_climb = 0.0;  // all samples
  double baseline_heldout_rms = 0.0;
  std::vector<HeadingFinding> findings;  // strongest first
  std::vector<HeadingFinding> dropped;   // chosen, then refuted (heading_diagnose.hpp yaw_noise_model)
  // Named, then left at the nominal: within the model's resolution (heading_select_resolution.hpp).
  std::vector<HeadingFinding> within_resolution;
  std::vector<HeadingAmbiguity> identifiability;  // every pair judged (selected links only)
  // The part of a yaw delay the servo's rows cannot place on either side
  // of the fin (s; heading_select_delay_side.hpp bound_delay_split).
  double delay_split_s = 0.0;
  // Every finding against every unused candidate: their signatures'
  // correlation, judged at or above the screen, stated below it.
  struct ScreenedCorrelation {
    HeadingEffect chosen = HeadingEffect::kFinDelay, alternative = HeadingEffect::kFinDelay;
    double correlation = 0.0;
  };
  std::vector<ScreenedCorrelation> screen;
  double screen_correlation = 0.0;
  HeadingValues values{};  // nominal with the findings
  double extended_rms = 0.0, extended_heldout_rms = 0.0;
  double gain = 0.0;
};

struct HeadingSelectOptions {
  fitting_core::Margins margins;        // fitting_core/selection.hpp; the absolute one in the link's unit (rad, rad/s)
  std::vector<HeadingEffect> fit_only;  // fit exactly these (no selection)
  // How the 95 % intervals count correlated samples (fitting_core/intervals.hpp;
  // LinkSamples::yo and phase name each sample's glide and yo).
  fitting_core::IntervalRule intervals = fitting_core::IntervalRule::kGlides;
  bool select = true;  // false (and no fit_only): the baseline alone
  // fit_only's effects fitted on every sample, the held-out yos too: a
  // measurement of named effects selects nothing, and a split by yo can put
  // every turn (what measures the fin) on the held-out side - health's box
  // turns fell on alternate yos and left the fin to the straight glides'
  // small corrections, read 0.55-1.01 (median 0.72) for 1 (docs/health.md
  // "Fin effectiveness on any launch heading"). The held-out scores are
  // then in-sample (no selection reads them).
  bool fit_on_all_samples = false;
  // Identifiability: an unused candidate whose signature correlates with a
  // finding's at least this much is fitted in its place (the vertical plane's
  // DiagnoseOptions::ambiguity_screen_correlation).
  double ambiguity_screen_correlation = 0.75;
};

struct LinkSamples {
  std::vector<std::size_t> all, train, heldout, dives, climbs;
  // By sample index: the sample's yo and phase (0 dive, 1 climb), for the
  // intervals' clusters; empty: every interval by the lag-1 rule.
  std::vector<int> yo, phase;
};

LinkFit select_heading_effects(HeadingLink link, const std::vector<HeadingEffect>& candidates,
                               const HeadingValues& nominal, const HeadingResiduals& residuals,
                               const LinkSamples& samples, const HeadingSelectOptions& options);

}  // namespace glider::diagnose
