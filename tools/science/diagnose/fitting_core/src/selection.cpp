// SPDX-License-Identifier: Apache-2.0
#include "glider/fitting_core/selection.hpp"

#include <algorithm>
#include <cmath>

namespace glider::fitting_core {

double margin(double heldout_rms, const Margins& margins) {
  return std::max(heldout_rms * margins.relative, margins.absolute);
}

bool improves_heldout(double a, double b, const Margins& margins) {
  return a < b * (1.0 - margins.relative) && a < b - margins.absolute;
}

bool beats(const Score& a, const Score& b, const Margins& margins) {
  return improves_heldout(a.heldout_rms, b.heldout_rms, margins) && a.bic < b.bic;
}

bool indistinguishable(double alternative_heldout_rms, double chosen_heldout_rms, const Margins& margins) {
  return alternative_heldout_rms <= chosen_heldout_rms + margin(chosen_heldout_rms, margins);
}

bool indistinguishable(const HeldOut& alternative, const HeldOut& chosen, const Margins& margins) {
  return indistinguishable(alternative.score, chosen.score, margins) ||
         indistinguishable(alternative.rms, chosen.rms, margins);
}

double bic(double rss, double n, double parameters) { return n * std::log(rss / n) + parameters * std::log(n); }

}  // namespace glider::fitting_core
