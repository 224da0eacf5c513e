// SPDX-License-Identifier: Apache-2.0
#pragma once
// The autopilot link under the two clocks its law may integrate over
// (heading_models.hpp AutopilotClock): the log's measured intervals, or its
// median cycle at every step. No public source says which a Slocum uses;
// two of the three comet logs cannot tell them apart, one prefers the
// measured (docs/science.md "The autopilot's clock"); on the independent
// truth, which integrates over its nominal cycle while its cycles jitter
// +-5 %, the clock moves the integrator by a few hundredths of a radian per
// wind-up - enough to name a spurious delay or deadband under the wrong
// clock, and to leave a narrow interval off the truth.
#include <vector>

#include "glider/diagnose/heading_fit.hpp"

namespace glider::diagnose {

enum class AutopilotClockRule : unsigned char {
  kMeasured,  // the measured intervals only (the rule before)
  kNominal,   // the log's median cycle only
  kBoth,      // both fitted, one reading: what both name, interval over both
  kHeldOut,   // the held-out rows choose where they tell the clocks apart, else kBoth
};

// What the two clocks' fits said, and what was kept.
struct AutopilotClockCheck {
  bool fitted = false;  // both clocks fitted
  double measured_heldout_rms = 0.0, nominal_heldout_rms = 0.0;
  // "measured" / "nominal": one clock's fit kept (the rule, or the held-out
  // rows told it); "both": the readings merged.
  const char* kept = "measured";
  std::vector<HeadingFinding> one_clock_only;  // named under one clock only: not findings
};

// One autopilot link from its two clocks' fits, by the rule (kBoth or
// kHeldOut; the other two replay one clock and merge nothing): where the
// held-out rows tell the clocks apart (kHeldOut; the selection's margins)
// that clock's fit; else the effects both name, each at the middle of its
// two readings with an interval spanning both clocks' intervals (the value
// is identifiable only up to the clock), the others stated in the check.
LinkFit merge_autopilot_clocks(const LinkFit& measured, const LinkFit& nominal, const HeadingValues& base,
                               AutopilotClockRule rule, double absolute_margin, AutopilotClockCheck& check);

}  // namespace glider::diagnose
