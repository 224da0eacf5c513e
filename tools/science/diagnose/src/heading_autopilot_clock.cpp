// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_autopilot_clock.hpp"

#include <algorithm>

#include "glider/fitting_core/selection.hpp"

namespace glider::diagnose {
namespace {

const HeadingFinding* named(const LinkFit& fit, HeadingEffect e) {
  for (const HeadingFinding& f : fit.findings) {
    if (f.effect == e) return &f;
  }
  return nullptr;
}

}  // namespace

LinkFit merge_autopilot_clocks(const LinkFit& measured, const LinkFit& nominal, const HeadingValues& base,
                               AutopilotClockRule rule, double absolute_margin, AutopilotClockCheck& check) {
  check = {};
  check.fitted = true;
  check.measured_heldout_rms = measured.extended_heldout_rms;
  check.nominal_heldout_rms = nominal.extended_heldout_rms;
  if (rule == AutopilotClockRule::kHeldOut) {
    fitting_core::Margins margins;
    margins.absolute = absolute_margin;
    if (fitting_core::improves_heldout(nominal.extended_heldout_rms, measured.extended_heldout_rms, margins)) {
      check.kept = "nominal";
      return nominal;
    }
    if (fitting_core::improves_heldout(measured.extended_heldout_rms, nominal.extended_heldout_rms, margins)) {
      return measured;
    }
  }
  check.kept = "both";
  LinkFit merged = measured;
  merged.findings.clear();
  merged.values = base;
  for (const HeadingFinding& m : measured.findings) {
    const HeadingFinding* n = named(nominal, m.effect);
    if (n == nullptr) {
      check.one_clock_only.push_back(m);
      continue;
    }
    HeadingFinding f = m;
    f.value = 0.5 * (m.value + n->value);
    f.ci95_low = std::min({m.ci95_low, n->ci95_low, m.value, n->value});
    f.ci95_high = std::max({m.ci95_high, n->ci95_high, m.value, n->value});
    at(merged.values, f.effect) = f.value;
    merged.findings.push_back(f);
  }
  for (const HeadingFinding& n : nominal.findings) {
    if (named(measured, n.effect) == nullptr) check.one_clock_only.push_back(n);
  }
  // The pairs and screens of a finding no longer named go with it.
  auto kept = [&](HeadingEffect e) { return named(merged, e) != nullptr; };
  std::erase_if(merged.identifiability, [&](const HeadingAmbiguity& a) { return !kept(a.chosen); });
  std::erase_if(merged.screen, [&](const LinkFit::ScreenedCorrelation& s) { return !kept(s.chosen); });
  // The gain removed with the findings kept: the last one's (cumulative).
  merged.gain = merged.findings.empty() ? 0.0 : merged.findings.back().gain;
  return merged;
}

}  // namespace glider::diagnose
