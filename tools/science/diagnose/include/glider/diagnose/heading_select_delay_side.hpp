// SPDX-License-Identifier: Apache-2.0
#pragma once
// A delay before the fin's effect on the yaw, read on either side of the fin
// (docs/science.md "The servo's dead time shorter than a row"). The servo
// link sees its dead time in the fin logged at the next row, and a fin that
// leaves a reading late still reaches the next one unless the move is long:
// with readings 6.7 s apart and a fin of 0.1 rad/s, a dead time of 1.6 s
// changes no logged m_fin, and the servo link names nothing. The vehicle
// link then moves the fin at the reading and reads the late fin as a late
// yaw - a yaw delay, where the truth's was the servo's. Within a row the two
// move the yaw alike (heading_models.cpp fin_between_rows: a fin behind a
// dead time leaves later but still reaches the next reading); only a move
// that the dead time would push past the next reading tells them apart.
#include "glider/diagnose/heading_fit.hpp"

namespace glider::diagnose {

// What the choice reads: each link's residuals and samples, the vehicle
// link's selection options (its margins) and the servo's margins.
struct DelaySides {
  const HeadingResiduals& servo_residuals;
  const LinkSamples& servo_samples;
  fitting_core::Margins servo_margins;
  const HeadingResiduals& yaw_residuals;
  const LinkSamples& yaw_samples;
  HeadingSelectOptions yaw_select;
};

// Where the vehicle link names a yaw delay and the servo link named no dead
// time, and the servo's rows cannot reject one as long as the yaw delay
// (its fin error with it within the servo's margins of its own), the same
// delay is put on the servo's side in the vehicle link (the fin leaving
// each reading behind it, the yaw delay at its nominal) and the held-out
// yos' rate error judges the two: the better stands, the pair stated
// (judged on the rate error where the signatures correlate at the link's
// screen, ambiguous within its margins). True when the delay moved to the
// servo's side (a fin_delay finding of the vehicle link).
bool choose_delay_side(LinkFit& yaw, const LinkFit& servo, const DelaySides& sides);

// Where a yaw delay stands beside the servo's dead time (named or nominal),
// the part of it the servo's rows cannot place: the longest extra dead time
// (0.25 s steps, up to the yaw delay) that its fin error cannot reject. The
// rows then allow every split of the two delays' sum over that part, so the
// yaw delay's 95 % interval reaches down by it and the servo's named dead
// time's up by it (the union of the intervals over the splits), and the
// vehicle link states it (LinkFit::delay_split_s). Returns the part (s).
double bound_delay_split(LinkFit& yaw, LinkFit& servo, const DelaySides& sides);

}  // namespace glider::diagnose
