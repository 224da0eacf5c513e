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
//
// Two forms of late: a pure delay (time stamps) or a first-order sensor (a
// pressure sensor's response; glider-truth's). They differ in the turns: a
// first-order lag delays a component of frequency w by lag / (1 + (w lag)^2),
// so a delay fitted to a sensor's lag reads it short (docs/science.md,
// "The vertical plane's thermal-expansion and depth-lag shortfall"). The
// diagnosis fits the form the held-out yos prefer (diagnose.cpp,
// choose_depth_lag_form).
#include <span>

namespace glider::diagnose {

enum class DepthLagForm { kDelay, kFirstOrder };
const char* to_string(DepthLagForm form);

// Replaces depth_m[k] (at time_s[k], increasing) by the depth as the sensor
// read it lag_s late, in `form`: delay_depth or first_order_lag.
// lag_s >= 0; 0 leaves the series as it is.
void read_depth_late(DepthLagForm form, std::span<const double> time_s, std::span<double> depth_m, double lag_s);

// The depth lag_s earlier, linearly interpolated; before the first sample,
// extrapolated along the first interval.
void delay_depth(std::span<const double> time_s, std::span<double> depth_m, double lag_s);

// A first-order sensor's reading of the depth (time constant lag_s, the
// depth straight between samples), started lag_s x the first interval's
// slope behind it (a run starts mid-glide, not from rest).
void first_order_lag(std::span<const double> time_s, std::span<double> depth_m, double lag_s);

}  // namespace glider::diagnose
