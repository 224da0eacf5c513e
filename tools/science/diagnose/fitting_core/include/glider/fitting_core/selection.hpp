// SPDX-License-Identifier: Apache-2.0
#pragma once
// Which effects a fit keeps: the rules every plane selects by, written once.
// An effect earns its place when the model with it predicts the held-out yos
// (fitted on the others) better than the model without it by a relative AND
// an absolute margin, and the Bayesian information criterion agrees. On long
// logs tiny model-structure mismatches become "significant" over tens of
// thousands of samples without being of any consequence: the margins say how
// much better is worth a finding. The same margins decide identifiability: an
// alternative that predicts the held-out yos within them cannot be told
// apart (identifiability.hpp).
namespace glider::fitting_core {

struct Margins {
  double relative = 0.03;  // fraction of the held-out RMS
  double absolute = 0.0;   // in the residual's unit (m/s of depth rate, rad of fin, ...)
};

// A fitted model as the selection sees it.
struct Score {
  double heldout_rms = 0.0;  // on the held-out yos
  double bic = 0.0;          // on the fitted yos
};

// The smallest change of held-out RMS the margins count: the larger of the two.
double margin(double heldout_rms, const Margins& margins);

// A held-out RMS `a` lower than `b` by both margins.
bool improves_heldout(double a, double b, const Margins& margins);

// `a` is better than `b` by the margins (held-out RMS) and by the BIC.
bool beats(const Score& a, const Score& b, const Margins& margins);

// The held-out yos cannot tell `alternative` from `chosen`: it is at most a
// margin worse.
bool indistinguishable(double alternative_heldout_rms, double chosen_heldout_rms, const Margins& margins);

// Two views of a fit's held-out error: the score the selection compares
// (residuals averaged over blocks of a glide, block_score.hpp; the plain RMS
// when blocks are off) and the sample-by-sample RMS it reports.
struct HeldOut {
  double score = 0.0;
  double rms = 0.0;
};

// Identifiability's verdict on two fits of the same data (an alternative
// in a finding's place): the held-out yos tell them apart only when BOTH
// views put the alternative beyond a margin. Where either cannot - e.g. the
// glide-averaged score separates a buoyancy offset from a uniform water
// velocity while the samples predict within 2 % (comet-2016, blocks of 60
// s) - the separation rests on a few glide means, and the pair is ambiguous.
bool indistinguishable(const HeldOut& alternative, const HeldOut& chosen, const Margins& margins);

// Bayesian information criterion of a least-squares fit: n ln(RSS / n) + k ln n.
double bic(double rss, double n, double parameters);

}  // namespace glider::fitting_core
