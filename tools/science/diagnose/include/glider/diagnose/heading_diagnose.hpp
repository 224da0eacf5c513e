// SPDX-License-Identifier: Apache-2.0
#pragma once
// The science loop in the heading plane: each link of the heading loop
// (servo, vehicle, autopilot; heading_effects.hpp) replayed on the log with
// its nominal model, its effects selected on alternate yos and scored on the
// others, the named cause, the extended vehicle and the autopilot flown.
#include <string>
#include <vector>

#include "glider/diagnose/heading_autopilot_clock.hpp"
#include "glider/diagnose/heading_closed_loop.hpp"
#include "glider/diagnose/heading_fit.hpp"
#include "glider/diagnose/heading_models.hpp"
#include "glider/diagnose/heading_shear.hpp"
#include "glider/diagnose/heading_track.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

// How often the autopilot left c_fin unchanged from one cycle to the next,
// by the heading error of the cycle before, among cycles whose heading rate
// was inside the rate deadband: a heading deadband shows as all held below
// it, none above (counted on the log, no model).
struct HoldBin {
  double from_rad = 0.0, to_rad = 0.0;
  std::size_t held = 0, changed = 0;
};

struct HeadingDiagnosis {
  std::string vehicle;
  AutopilotSettings configured;  // the law the log's header states
  double fin_max_rad = 0.0;
  bool roll_logged = false;
  double logged_roll_rad = 0.0;  // median m_roll on the glides used
  std::size_t runs = 0;          // glides under a heading command
  // The autopilot link's integrator a state per glide (false: replayed from
  // the log's start; HeadingDiagnoseOptions::autopilot_integrator_per_glide).
  bool autopilot_integrator_per_glide = false;
  AutopilotClockCheck autopilot_clock;  // the autopilot link under both clocks
  // The heading's cycle-to-cycle jitter on the glides, as white noise
  // (sqrt(2/3) x the RMS of half the second difference): compass noise and
  // yaw faster than the cycle, which no link explains. The SIL's compass
  // noise when the log is replayed.
  double heading_noise_rad = 0.0;
  // What the extended yaw model leaves of the measured yaw rate: its RMS and
  // the lag at which its autocorrelation within a glide falls below 1/e (a
  // slow yaw disturbance, not compass noise, when that is tens of seconds).
  double unexplained_yaw_rate_rad_s = 0.0;
  double unexplained_correlation_s = 0.0;
  // The compass noise and random yaw the fin and the yaw's time constant
  // were measured with on the heading's innovations (heading_rad 0: not
  // measured - the vehicle link named neither, nor a roll offset, or
  // yaw_noise_model is off).
  YawNoise yaw_noise;
  // The current's vertical shear across the heading, from what the
  // extended yaw model leaves (heading_shear.hpp); the unexplained yaw
  // above is what is left after it.
  ShearProfile current_shear;
  std::vector<HoldBin> holds;  // 0-2, 2-4, ... 10-12 deg, and beyond
  LinkFit servo, yaw, autopilot;
  // The autopilot link flown closed-loop (heading_closed_loop.hpp): how well
  // the identified loop reproduces where the log's loop settles and how hard
  // it works the fin, and what each left-out candidate would change.
  ClosedLoopCheck closed_loop;
  HeadingValues values{};      // every link's nominal with its findings
  std::string cause = "none";  // the finding with the largest gain of its link
  // The loop's dead time by where it sits (s): heading reading -> c_fin
  // (the autopilot's cycle), c_fin -> m_fin (the servo), m_fin -> yaw
  // response (compass filtering, the vehicle).
  double delay_autopilot_s = 0.0, delay_servo_s = 0.0, delay_after_fin_s = 0.0;
  // The yaw's fast pole the vehicle link's models carried (the prior's centre
  // where a yaw delay is, at most the delay: carried_fast_pole; 0 without one), and
  // its prior's upper end (HeadingTrackOptions::yaw_fast_pole_max_s): the
  // after-fin delay is a dead time beside it, its interval widened by the
  // prior (0: no fast pole).
  double yaw_fast_pole_s = 0.0, yaw_fast_pole_max_s = 0.0;
  // The fast pole read beside the lag (HeadingDiagnoseOptions::
  // yaw_lag_fast_pole; 0: none) and the poles whose readings its intervals span.
  double yaw_lag_pole_s = 0.0, yaw_lag_pole_low_s = 0.0, yaw_lag_pole_high_s = 0.0;
};

struct HeadingDiagnoseOptions {
  // The diagnosis carries the yaw's fast pole (HeadingTrackOptions::
  // yaw_fast_pole_max_s: half the vehicle file's yaw time constant).
  HeadingTrackOptions track{.yaw_fast_pole_max_s = -1.0};
  std::size_t max_fit_samples = 4000;  // per half, even stride (the fits' cost)
  // Where the vehicle link names fin_effectiveness, roll_offset or
  // yaw_time_constant (chosen on the yaw rate of the logged fin, which reads
  // the fin weak, a stronger fin as a roll offset and the yaw's lag long or
  // as a weaker fin in a closed loop), the fin and the lag measured together
  // on the heading's one-step innovations with the compass noise and the
  // random yaw modelled (heading_models.hpp heading_innovations), no finding
  // where an interval holds the vehicle file's value, and the rest of the
  // link selected again with those held; false: the rate error's selection
  // (docs/science.md "The fin's authority in a closed loop", "The fin
  // measured whenever the rate error names the fin or a roll offset", "The
  // yaw's lag in a closed loop and the fin's roll"). Not with fit_only (a
  // measurement of named effects, e.g. health's on decimated logs, whose
  // headings are interpolated between readings: the innovations need every
  // heading reading as logged).
  bool yaw_noise_model = true;
  // With yaw_noise_model, where the vehicle link's rate error names no yaw
  // time constant: the lag, then the yaw's delay, probed on the innovations
  // (each alone beside the fin); the lag stands where the held-out yos'
  // innovations are better predicted with it by the selection's margins and
  // better than with the delay alone (or the delay stands too: then the
  // better of the two is named, the other stated where the margins cannot
  // tell them apart). The probe runs only where a cheap screen (the lag
  // alone on its grid, the noise refined once) predicts the held-out
  // innovations better by half the selection's margin. false: the rule
  // before, the lag and delay measured only
  // where the rate error named them (docs/science.md "The yaw's lag probed
  // on the innovations").
  bool yaw_dynamics_probe = true;
  // Where the innovations measure the yaw's lag beside the fin (no yaw
  // delay): the lag and fin measured again with the fast pole at its
  // prior's centre and upper end; the likeliest of the three readings
  // (pole 0 among them) stands, its intervals spanning the readings whose
  // likelihood the log cannot tell from the likeliest's. false: no pole
  // beside the lag, the rule before (docs/science.md "The yaw's lag beside
  // the fast pole, profiled").
  bool yaw_lag_fast_pole = true;
  std::vector<HeadingEffect> fit_only;  // fit exactly these (in their links), no selection
  bool fit_on_all_samples = false;      // fit_only on the held-out yos too (HeadingSelectOptions)
  fitting_core::IntervalRule intervals = fitting_core::IntervalRule::kGlides;  // HeadingSelectOptions
  // Fly the closed-loop check (heading_closed_loop.hpp; not with fit_only).
  bool closed_loop = true;
  // The autopilot's integrator at each glide's start: a state per glide,
  // profiled out of the autopilot link's residuals (its mean over the
  // glide's unclamped rows) instead of replayed from the log's start - a
  // law that integrates over another clock than the log's intervals gains
  // or loses integrator in each wind-up, a constant miss for the rest of the
  // glide. false: replayed (the rule before; docs/science.md "The
  // autopilot's integrator at each glide's start").
  bool autopilot_integrator_per_glide = true;
  // The clock the autopilot's law integrates over (heading_autopilot_clock.hpp;
  // not with fit_only: a measurement of named effects keeps the measured one).
  AutopilotClockRule autopilot_clock = AutopilotClockRule::kBoth;
};

struct UnexplainedYaw {
  double rms_rad_s = 0.0;      // of the yaw rate the model leaves (the slope estimator's)
  double correlation_s = 0.0;  // first lag where its autocorrelation within a glide < 1/e (0: none found)
};
// What the yaw model with these values leaves of a track's measured yaw rate.
// With `shear`, the yaw its profile makes is part of the model.
UnexplainedYaw unexplained_yaw(const HeadingTrack& track, const model::VehicleParams& vehicle,
                               const HeadingValues& values, const ShearProfile* shear = nullptr);

// The configured autopilot from the log's settings_at_file_open
// (u_hd_fin_ap_gain, _igain, _dgain, u_heading_rate_deadband).
AutopilotSettings configured_autopilot(const flightlog::FlightLog& log);

// Throws HeadingUnavailable (names what the log lacks).
HeadingDiagnosis diagnose_heading(const model::VehicleParams& nominal, const flightlog::FlightLog& log,
                                  const HeadingDiagnoseOptions& options = {});

// The nominal vehicle with the vehicle and servo findings: fin dead time =
// servo + after-fin delay, fin yaw gain x effectiveness, yaw time constant,
// roll = the log's median roll + the offset found, the fin limit the log
// states.
model::VehicleParams apply(model::VehicleParams nominal, const HeadingDiagnosis& d);

}  // namespace glider::diagnose
