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
#include <vector>

#include "glider/diagnose/flight_model.hpp"

namespace glider::diagnose {

enum class DepthLagForm { kDelay, kFirstOrder };
const char* to_string(DepthLagForm form);

// Replaces depth_m[k] (at time_s[k], increasing) by the depth as the sensor
// read it lag_s late, in the form of the DepthLagView whose predict() is
// running (a delay outside any): see delay_only / first_order_lag.
// lag_s >= 0; 0 leaves the series as it is. (The dynamic flight model calls
// it as it reads each run; the form reaches it through the view.)
void delay_depth(std::span<const double> time_s, std::span<double> depth_m, double lag_s);

// The depth lag_s earlier, linearly interpolated; before the first sample,
// extrapolated along the first interval.
void delay_only(std::span<const double> time_s, std::span<double> depth_m, double lag_s);

// A first-order sensor's reading of the depth (time constant lag_s, the
// depth straight between samples), started lag_s x the first interval's
// slope behind it (a run starts mid-glide, not from rest).
void first_order_lag(std::span<const double> time_s, std::span<double> depth_m, double lag_s);

// A dynamic flight model read with the depth lag in one form. The same model
// may sit under both views: each asks it with the depth lag's sign its own
// (+|lag| a delay, -|lag| a first-order sensor) - the model reads |lag|
// ("no sign, as the pump's") and keeps its answers by the values' bits, so
// the two forms never share an answer while they share every flight (which
// does not depend on the depth lag). Every fit of a diagnosis asks through a
// view, so no other sign reaches the model.
class DepthLagView final : public DepthRateModel {
 public:
  DepthLagView(const DepthRateModel& model, DepthLagForm form) : model_(model), form_(form) {}
  DepthLagForm form() const { return form_; }
  void predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
               std::vector<double>& out, const VerticalVelocityProfile* profile = nullptr) const override;
  void predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                     std::vector<double>& out) const override;
  double ctd_density_anomaly() const override { return model_.ctd_density_anomaly(); }
  std::span<const double> measured_speed_m_s() const override { return model_.measured_speed_m_s(); }

 private:
  EffectValues signed_lag(const EffectValues& values) const;
  const DepthRateModel& model_;
  DepthLagForm form_;
};

}  // namespace glider::diagnose
