// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading loop closed on the log (issue 26): the autopilot, the servo and
// the yaw model of heading_models.hpp, with the current's shear, flown
// together from each glide's first logged heading under the logged heading
// commands - the heading is the model's own, not the log's. What the
// open-loop links cannot see shows here: an autopilot deadband or a delay
// that changes c_fin little changes where the closed loop settles (its steady
// heading error), which is what a replay in SIL flies.
#include <cstddef>
#include <functional>
#include <vector>

#include "glider/diagnose/heading_effects.hpp"
#include "glider/diagnose/heading_fit.hpp"
#include "glider/diagnose/heading_models.hpp"
#include "glider/diagnose/heading_shear.hpp"
#include "glider/diagnose/heading_track.hpp"
#include "glider/fitting_core/selection.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

// One glide of the track flown closed-loop: the mean heading error (command -
// heading, rad) over its scored samples, simulated and logged.
struct ClosedLoopGlide {
  std::size_t run = 0;
  int yo = 0;
  bool dive = false;
  double simulated_error_rad = 0.0, logged_error_rad = 0.0;
  // How much the autopilot moves the fin over the scored samples: the sum
  // of |c_fin| steps per second (rad/s), the model's and the log's.
  double simulated_fin_travel_rad_s = 0.0, logged_fin_travel_rad_s = 0.0;
};

struct ClosedLoopOptions {
  // White compass noise on the heading the model's autopilot reads (rad; the
  // diagnosis's heading_noise_rad): a deadband holds the fin only while the
  // noisy error stays inside it. Drawn from a fixed seed, the same draws for
  // every set of values compared (common random numbers).
  double heading_noise_rad = 0.0;
  unsigned seed = 1;
};

// Every run of the track with a scored sample, flown closed-loop with `values`
// (all three links) in the `shear` (nullptr: still water).
std::vector<ClosedLoopGlide> fly_closed_loop(const HeadingTrack& track, const model::VehicleParams& vehicle,
                                             const AutopilotSettings& settings, const HeadingValues& values,
                                             const ShearProfile* shear, const ClosedLoopOptions& options = {});

}  // namespace glider::diagnose

namespace glider::diagnose {

// The closed-loop check of the autopilot link (docs/diagnose/heading.md, "The
// closed-loop check"): the configured law, the open-loop selection's set and
// that set with each candidate it left out, each flown closed-loop with its
// open-loop fit on c_fin (the servo and vehicle findings and the shear the
// plant). Each glide is scored on two features, model against log: where the
// loop settles (the mean heading error) and how hard it works (the fin
// travel), each in units of the log's own glide-to-glide scatter of that
// feature (pooled within dives and climbs) - a closed loop's heading cannot
// be matched sample by sample (the water's disturbances are not modelled),
// these two can. The score is the RMS of both over the held-out glides (odd
// yos). A measurement, not a selection: on the independent truth, admitting
// effects by it took the plant's missing lag (the truth's second yaw pole,
// its fin-induced roll) as autopilot_delay (docs/science.md).
struct ClosedLoopScore {
  double score = 0.0;             // the RMS of the scaled features, held-out glides
  double error_rms_rad = 0.0;     // of the mean heading error, model - log
  double travel_rms_rad_s = 0.0;  // of the fin travel, model - log
  double bic = 0.0;               // of the scaled features on the fitted glides (even yos)
};
struct ClosedLoopCandidate {
  HeadingEffect effect = HeadingEffect::kAutopilotGain;
  double value = 0.0;     // in the open-loop fit of the set with it
  ClosedLoopScore score;  // of the set with it
  bool beats = false;     // beats the open-loop set by the selection's margins and the BIC
};
struct ClosedLoopCheck {
  ClosedLoopScore configured, open_loop_set;
  std::vector<ClosedLoopCandidate> candidates;                 // each left out, added to the open-loop set
  double error_scatter_rad = 0.0, travel_scatter_rad_s = 0.0;  // the log's, the features' units
  std::size_t train_glides = 0, heldout_glides = 0;
};

// `fit`: the autopilot link's open-loop fit of exactly these effects; `fly`:
// the closed loop with these values (every link's); `plant`: the values of
// the servo and vehicle links; `margins`: in units of the scatter.
ClosedLoopCheck check_autopilot_closed_loop(
    const std::vector<HeadingEffect>& open_loop, const std::vector<HeadingEffect>& candidates,
    const HeadingValues& plant, const std::function<LinkFit(const std::vector<HeadingEffect>&)>& fit,
    const std::function<std::vector<ClosedLoopGlide>(const HeadingValues&)>& fly, const fitting_core::Margins& margins);

}  // namespace glider::diagnose
