// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_select_resolution.hpp"

#include <algorithm>
#include <cmath>

namespace glider::diagnose {

bool drop_lag_within_resolution(LinkFit& yaw, const HeadingValues& nominal, double fast_pole_s) {
  constexpr HeadingEffect kLag = HeadingEffect::kYawTimeConstant;
  const auto lag =
      std::find_if(yaw.findings.begin(), yaw.findings.end(), [](const HeadingFinding& f) { return f.effect == kLag; });
  if (lag == yaw.findings.end()) return false;
  // Either way: a fast pole adds to the slow one, the fin's roll turning the
  // glider back makes the yaw settle sooner (a lag of 1.25 s for 2 s).
  // The lag beside a fast pole the model carries reads shorter by it (the
  // log measures their sum): compared as the lag a first-order yaw lumps.
  if (!(std::abs(lag->value + fast_pole_s - at(nominal, kLag)) <= kYawLagResolutionS)) return false;
  yaw.within_resolution.push_back(*lag);
  yaw.findings.erase(lag);
  at(yaw.values, kLag) = at(nominal, kLag);
  std::erase_if(yaw.identifiability, [](const HeadingAmbiguity& a) { return a.chosen == kLag; });
  std::erase_if(yaw.screen, [](const LinkFit::ScreenedCorrelation& c) { return c.chosen == kLag; });
  return true;
}

}  // namespace glider::diagnose
