// SPDX-License-Identifier: Apache-2.0
// The closed-loop check of the autopilot link (heading_closed_loop.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "glider/diagnose/heading_closed_loop.hpp"
#include "glider/fitting_core/selection.hpp"

namespace glider::diagnose {
namespace {

// Below these the log's scatter is no unit (glides that all settle alike).
constexpr double kErrorScatterFloorRad = 0.25 * std::numbers::pi / 180.0;
constexpr double kTravelScatterFloorRadS = 1e-5;

// The log's glide-to-glide scatter of a feature, pooled within dives and
// climbs (each direction's own mean taken out), at least `floor`.
double pooled_scatter(const std::vector<ClosedLoopGlide>& glides, double ClosedLoopGlide::*feature, double floor) {
  double sum[2] = {0.0, 0.0}, n[2] = {0.0, 0.0};
  for (const ClosedLoopGlide& g : glides) {
    sum[g.dive ? 1 : 0] += g.*feature;
    n[g.dive ? 1 : 0] += 1.0;
  }
  double ss = 0.0;
  for (const ClosedLoopGlide& g : glides) {
    const int d = g.dive ? 1 : 0;
    const double x = g.*feature - sum[d] / n[d];
    ss += x * x;
  }
  const double dof = static_cast<double>(glides.size()) - (n[0] > 0.0 ? 1.0 : 0.0) - (n[1] > 0.0 ? 1.0 : 0.0);
  return dof > 0.0 ? std::max(floor, std::sqrt(ss / dof)) : floor;
}

class Scorer {
 public:
  Scorer(const HeadingValues& plant, const std::function<LinkFit(const std::vector<HeadingEffect>&)>& fit,
         const std::function<std::vector<ClosedLoopGlide>(const HeadingValues&)>& fly)
      : plant_(plant), fit_(fit), fly_(fly) {}

  // The set's open-loop fit flown closed-loop; `link` gets the fit.
  ClosedLoopScore score(const std::vector<HeadingEffect>& set, LinkFit& link) {
    link = fit_(set);
    HeadingValues v = plant_;
    for (std::size_t i = 0; i < kHeadingEffectCount; ++i) {
      if (info(static_cast<HeadingEffect>(i)).link == HeadingLink::kAutopilot) v[i] = link.values[i];
    }
    const std::vector<ClosedLoopGlide> glides = fly_(v);
    if (error_scatter_ == 0.0) {  // the log's features: the same whatever the values
      error_scatter_ = pooled_scatter(glides, &ClosedLoopGlide::logged_error_rad, kErrorScatterFloorRad);
      travel_scatter_ = pooled_scatter(glides, &ClosedLoopGlide::logged_fin_travel_rad_s, kTravelScatterFloorRadS);
    }
    double train_ss = 0.0, heldout_ss = 0.0, error_ss = 0.0, travel_ss = 0.0;
    train_ = heldout_ = 0;
    for (const ClosedLoopGlide& g : glides) {
      const double error = g.simulated_error_rad - g.logged_error_rad;
      const double travel = g.simulated_fin_travel_rad_s - g.logged_fin_travel_rad_s;
      const double ss = std::pow(error / error_scatter_, 2) + std::pow(travel / travel_scatter_, 2);
      if (g.yo % 2 == 0) {
        train_ss += ss;
        ++train_;
      } else {
        heldout_ss += ss;
        error_ss += error * error;
        travel_ss += travel * travel;
        ++heldout_;
      }
    }
    ClosedLoopScore out;
    if (heldout_ > 0) {
      const double n = static_cast<double>(heldout_);
      out.score = std::sqrt(heldout_ss / (2.0 * n));
      out.error_rms_rad = std::sqrt(error_ss / n);
      out.travel_rms_rad_s = std::sqrt(travel_ss / n);
    }
    // A threshold's grid is a parameter too (heading_fit.cpp's BIC); two features per glide.
    const auto grids = std::count_if(set.begin(), set.end(), [](HeadingEffect e) { return info(e).grid; });
    const double k = static_cast<double>(set.size()) + static_cast<double>(grids);
    if (train_ > 0) out.bic = fitting_core::bic(std::max(train_ss, 1e-300), 2.0 * static_cast<double>(train_), k);
    return out;
  }
  double error_scatter() const { return error_scatter_; }
  double travel_scatter() const { return travel_scatter_; }
  std::size_t train() const { return train_; }
  std::size_t heldout() const { return heldout_; }

 private:
  HeadingValues plant_;
  const std::function<LinkFit(const std::vector<HeadingEffect>&)>& fit_;
  const std::function<std::vector<ClosedLoopGlide>(const HeadingValues&)>& fly_;
  double error_scatter_ = 0.0, travel_scatter_ = 0.0;
  std::size_t train_ = 0, heldout_ = 0;
};

}  // namespace

ClosedLoopCheck check_autopilot_closed_loop(
    const std::vector<HeadingEffect>& open_loop, const std::vector<HeadingEffect>& candidates,
    const HeadingValues& plant, const std::function<LinkFit(const std::vector<HeadingEffect>&)>& fit,
    const std::function<std::vector<ClosedLoopGlide>(const HeadingValues&)>& fly,
    const fitting_core::Margins& margins) {
  ClosedLoopCheck out;
  Scorer scorer(plant, fit, fly);
  LinkFit link;
  out.configured = scorer.score({}, link);
  out.open_loop_set = scorer.score(open_loop, link);
  out.train_glides = scorer.train();
  out.heldout_glides = scorer.heldout();
  out.error_scatter_rad = scorer.error_scatter();
  out.travel_scatter_rad_s = scorer.travel_scatter();
  for (HeadingEffect e : candidates) {
    if (std::find(open_loop.begin(), open_loop.end(), e) != open_loop.end()) continue;
    std::vector<HeadingEffect> set = open_loop;
    set.push_back(e);
    ClosedLoopCandidate c;
    c.effect = e;
    c.score = scorer.score(set, link);
    c.value = at(link.values, e);
    c.beats =
        fitting_core::beats({c.score.score, c.score.bic}, {out.open_loop_set.score, out.open_loop_set.bic}, margins);
    out.candidates.push_back(c);
  }
  return out;
}

}  // namespace glider::diagnose
