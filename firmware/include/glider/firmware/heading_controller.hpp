// SPDX-License-Identifier: Apache-2.0
#pragma once
// Rudder (fin) autopilot. Three laws, so SIL can compare them on the same
// vehicle (docs/heading-control.md):
// - kProportional: paper 001's fin = kp (psi_c - psi), kp 0.5 deg/deg.
// - kSlocum: the Slocum heading autopilot as its logged settings describe it:
//   fin = gain e + igain int(e) + dgain r, r the heading rate with the
//   u_heading_rate_deadband; the integrator runs unconditionally and is
//   clamped only by the fin limit on the output; with a heading deadband
//   the fin is held while error and rate are both inside theirs.
// - kCompensated: the same gains, plus what the glider's fin servo needs:
//   the error is taken on the heading predicted `delay_s` ahead (a Smith
//   predictor: the turn the fin commands already sent will make, from the
//   fin's yaw authority, plus the slowly varying turn the fin does not
//   explain, e.g. a static roll's), the commanded fin
//   never moves faster than the servo can follow, an error deadband, and an
//   integrator that may only shrink while the fin is saturated, kept per
//   glide direction (a static roll needs opposite fins on dives and climbs:
//   one integrator would unlearn it at every inflection).
#include <array>
#include <cstdint>

namespace glider::fw {

enum class HeadingLaw : std::int32_t { kProportional = 0, kSlocum = 1, kCompensated = 2 };

struct HeadingControlConfig {
  HeadingLaw law = HeadingLaw::kCompensated;
  double kp = 0.5;                      // kProportional, rad/rad (paper 001)
  double gain = 1.5;                    // u_hd_fin_ap_gain, rad of fin per rad of error
  double igain = 0.02;                  // u_hd_fin_ap_igain, rad per rad s
  double dgain = -4.0;                  // u_hd_fin_ap_dgain, rad per rad/s of heading rate
  double rate_deadband_rad_s = 0.0087;  // u_heading_rate_deadband
  // kSlocum: u_heading_deadband. While the error is inside it and the rate
  // inside rate_deadband_rad_s the fin is held where it is (and nothing
  // integrates); 0 = never held. The comet logs hold the fin below ~5 deg
  // (glider-diagnose's autopilot_deadband, docs/heading-control.md).
  double heading_deadband_rad = 0.0;
  double fin_max_rad = 0.25;  // f_fin_safety_max (comet 2019)
  // kCompensated only:
  double fin_rate_rad_s = 0.1;         // the servo's speed (the vehicle file's fin_rate_rad_s)
  double delay_s = 0.0;                // the fin's dead time to predict over
  double error_deadband_rad = 0.0087;  // no correction inside +-0.5 deg
  double rate_filter_s = 3.0;          // first-order filter of the heading rate (compass noise)
  double disturbance_filter_s = 30.0;  // filter of the turn rate the fin does not explain
  double fin_deadband_rad = 0.02;      // smaller moves are not made (each one costs energy)
  // Yaw rate per fin angle per speed through the water (the vehicle's
  // fin_yaw_gain_per_m), for the predictor's pending-fin term; 0 = rate only.
  double yaw_gain_per_m = 0.0;
};

class HeadingController {
 public:
  explicit HeadingController(const HeadingControlConfig& config) : config_(config) {}

  // The fin is held centred this cycle (surface, abort, no heading to fly):
  // the integrators are kept, the rate estimate is dropped, and the centred
  // fin goes into the command history the predictor uses.
  void centre() {
    have_heading_ = false;
    fin_ = 0.0;
    history_[history_next_] = 0.0;
    history_next_ = (history_next_ + 1) % kHistory;
  }
  void reset() {
    integrator_ = 0.0;
    fin_ = 0.0;
    have_heading_ = false;
  }

  // kCompensated: the glide direction the next updates are for (swaps in
  // that direction's integrator).
  void select_glide(bool diving);

  // heading and target in rad (0 north, clockwise); dt_s > 0; speed the
  // horizontal speed through the water (for the predictor). Returns the fin
  // command in rad, + turns clockwise.
  double update(double heading_rad, double target_rad, double dt_s, double speed_m_s = 0.0);

  double fin() const { return fin_; }
  double integrator() const { return integrator_; }
  double heading_rate() const { return rate_; }

 private:
  double clamp_fin(double fin) const;
  double update_compensated(double heading_rad, double target_rad, double dt_s, double rate, double speed_m_s);

  // Fin commands of the last kHistory cycles, newest last (the predictor's
  // pending fins).
  static constexpr std::size_t kHistory = 64;
  std::array<double, kHistory> history_{};
  std::size_t history_next_ = 0;

  HeadingControlConfig config_;
  double integrator_ = 0.0;        // rad of fin
  double other_integrator_ = 0.0;  // kCompensated: the other glide direction's
  bool diving_ = true;
  double filtered_rate_ = 0.0;
  double disturbance_ = 0.0;  // rad/s of turn not from the fin (Smith predictor)
  double fin_ = 0.0;
  double rate_ = 0.0;
  double last_heading_ = 0.0;
  bool have_heading_ = false;
};

}  // namespace glider::fw
