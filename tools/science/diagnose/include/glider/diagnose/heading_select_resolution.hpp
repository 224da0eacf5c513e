// SPDX-License-Identifier: Apache-2.0
#pragma once
// The yaw's first-order lag read at the model's resolution (docs/science.md
// "The yaw's lag within the fast pole it lumps"). The vehicle link's yaw
// relaxes to its target with one time constant (heading_models.hpp); a
// glider's yaw has faster dynamics besides the slow pole - a second pole of
// the yaw itself, the fin's roll turning the glider back against the fin -
// and a first-order fit lumps them into its lag: a two-pole yaw
// tau1 tau2 r'' + (tau1 + tau2) r' + r = target reads as one lag of about
// tau1 + tau2. They show where the loop works the fin hard and fast (a long
// servo or autopilot delay, a deep log): there the rate error named lags of
// 2.78-3.18 s for the vehicle file's 2 s, each one side of an ambiguous pair
// with a dead time of 0.65-1.17 s, where the independent truth's fast pole
// was 0.86-0.96 s; and the fin's roll, which turns the glider back against
// the fin a few seconds on, makes the yaw settle sooner and the lag read
// short (a fin delay of 11.2 s, deep: a lag of 1.25 s named for 2 s). Such a
// lag is no evidence that the slow pole moved.
#include "glider/diagnose/heading_effects.hpp"
#include "glider/diagnose/heading_fit.hpp"

namespace glider::diagnose {

// The dynamics a first-order yaw lumps into its lag (s): a fast pole of up
// to a second and a fraction of one from the fin's roll.
constexpr double kYawLagResolutionS = 1.25;

// A named yaw time constant within kYawLagResolutionS of the vehicle
// file's (with the fast pole the model carried added: what a first-order
// yaw would have read; HeadingTrack::yaw_fast_pole_s) leaves the link's
// findings for `within_resolution`:
// its value back at the nominal, its pairs no longer stated. The other
// findings stand as fitted. True when one was moved.
bool drop_lag_within_resolution(LinkFit& yaw, const HeadingValues& nominal, double fast_pole_s = 0.0);

}  // namespace glider::diagnose
