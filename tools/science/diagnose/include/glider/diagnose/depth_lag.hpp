// SPDX-License-Identifier: Apache-2.0
#pragma once
// The measured depth late against the inputs that fly the model (the
// diagnosis's depth_lag): a pressure sensor's response, or time stamps of a
// science computer's CTD that are behind the flight computer's pitch and
// ballast (on comet-2016 the CTD's pressure trails m_depth by ~1.3 s). On a
// steady glide a late depth changes nothing; in a turn, where the pitch and
// the pump move within half a minute, it reads the model's turn as early.
// Left out, a vertical-velocity profile absorbs it: + at the bottom turn
// (the late depth still sinks), - at the top.
#include <span>

namespace glider::diagnose {

// Replaces depth_m[k] (at time_s[k], increasing) by the depth lag_s earlier,
// linearly interpolated; before the first sample, extrapolated along the
// first interval. lag_s >= 0; 0 leaves the series as it is.
void delay_depth(std::span<const double> time_s, std::span<double> depth_m, double lag_s);

}  // namespace glider::diagnose
