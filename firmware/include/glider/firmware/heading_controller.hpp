#pragma once
// Rudder (fin) autopilot. Three laws, so SIL can compare them on the same
// vehicle (docs/heading-control.md):
// - kProportional: paper 001's fin = kp (psi_c - psi), kp 0.5 deg/deg.
// - kSlocum: the Slocum heading autopilot as its logged settings describe it:
//   fin = gain e + igain int(e) + dgain r, r the heading rate with the
//   u_heading_rate_deadband; the integrator runs unconditionally and is
//   clamped only by the fin limit on the output.
// - kCompensated: the same gains, plus what the glider's fin servo needs:
//   the error is taken on the heading predicted `delay_s` ahead (the fin's
//   dead time), the commanded fin never moves faster than the servo can
//   follow, an error deadband, and an integrator that may only shrink while
//   the fin is saturated (so a roll offset's steady fin is learnt without
//   winding up through turns).
#include <cstdint>

namespace glider::fw {

enum class HeadingLaw : std::int32_t { kProportional = 0, kSlocum = 1, kCompensated = 2 };

struct HeadingControlConfig {
  HeadingLaw law = HeadingLaw::kCompensated;
  double kp = 0.5;                    // kProportional, rad/rad (paper 001)
  double gain = 1.5;                  // u_hd_fin_ap_gain, rad of fin per rad of error
  double igain = 0.02;                // u_hd_fin_ap_igain, rad per rad s
  double dgain = -4.0;                // u_hd_fin_ap_dgain, rad per rad/s of heading rate
  double rate_deadband_rad_s = 0.0087;  // u_heading_rate_deadband
  double fin_max_rad = 0.25;          // f_fin_safety_max (comet 2019)
  // kCompensated only:
  double fin_rate_rad_s = 0.1;        // the servo's speed (the vehicle file's fin_rate_rad_s)
  double delay_s = 0.0;               // the fin's dead time to predict over
  double error_deadband_rad = 0.0087; // no correction inside +-0.5 deg
};

class HeadingController {
 public:
  explicit HeadingController(const HeadingControlConfig& config) : config_(config) {}

  // Restart (e.g. a new glide): integrator kept, rate estimate dropped.
  void reset_rate() { have_heading_ = false; }
  void reset() {
    integrator_ = 0.0;
    fin_ = 0.0;
    have_heading_ = false;
  }

  // heading and target in rad (0 north, clockwise); dt_s > 0. Returns the fin
  // command in rad, + turns clockwise.
  double update(double heading_rad, double target_rad, double dt_s);

  double fin() const { return fin_; }
  double integrator() const { return integrator_; }
  double heading_rate() const { return rate_; }

 private:
  double clamp_fin(double fin) const;

  HeadingControlConfig config_;
  double integrator_ = 0.0;  // rad of fin
  double fin_ = 0.0;
  double rate_ = 0.0;
  double last_heading_ = 0.0;
  bool have_heading_ = false;
};

}  // namespace glider::fw
