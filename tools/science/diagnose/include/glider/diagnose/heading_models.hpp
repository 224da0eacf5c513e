// SPDX-License-Identifier: Apache-2.0
#pragma once
// The three links of the heading loop as the diagnosis replays them on a
// log (heading_effects.hpp), each with the effects of its link applied:
// - the servo: m_fin from the logged c_fin through the vehicle's dead time
//   and fin speed;
// - the vehicle: the yaw rate from the logged m_fin, speed, lift factor and
//   roll through the model's first-order yaw (model/dynamics.hpp), compared
//   through the same slope estimator as the measured yaw rate;
// - the autopilot: c_fin from the logged heading and command by Slocum's law
//   (fin = gain e + integral + dgain r, clamped; firmware/heading_controller).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "glider/diagnose/heading_effects.hpp"
#include "glider/diagnose/heading_track.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

// The autopilot a log's header configures (u_hd_fin_ap_*), as nominal values.
struct AutopilotSettings {
  double gain = 1.5, igain = 0.02, dgain = -4.0;  // the firmware's defaults (Slocum's in the comet logs)
  double rate_deadband_rad_s = 0.0087;
  double heading_deadband_rad = 0.0;  // u_heading_deadband: 0 = the fin is never held
  bool stated = false;                // false: the log's header states none (the defaults stand in)
};

// Slocum's heading law, one cycle: the fin held (output unchanged, nothing
// integrated) inside both deadbands, else PID with the integrator unclamped
// and only the output clamped, as the firmware's. The open-loop replay
// (predict_autopilot_fin) and the closed loop (fly_closed_loop) both step it.
struct AutopilotLaw {
  double kp = 0.0, ki = 0.0, kd = 0.0, hold_below = 0.0, rate_deadband = 0.0, fin_max = 0.0;
  double integrator = 0.0, output = 0.0;
  // The law with the values' gains, deadband and this log's fin limit.
  static AutopilotLaw from(const HeadingValues& values, const AutopilotSettings& settings, double fin_max_rad);
  double step(double error, double rate, double dt) {
    const bool still = std::abs(rate) < rate_deadband;
    return step_read(error, still ? 0.0 : rate, still, dt);
  }
  // One cycle on a rate already read against the rate deadband (`still`:
  // inside it, the rate 0): the replay reads it once per delay, and the
  // test on the heading deadband (0 unless fitted) goes first - it is the
  // one a branch predictor can guess.
  double step_read(double error, double rate, bool still, double dt) {
    if (std::abs(error) < hold_below && still) return output;
    integrator += ki * error * dt;
    output = std::clamp(kp * error + integrator + kd * rate, -fin_max, fin_max);
    return output;
  }
};

// The values that mean "no effect" for this vehicle and configured law.
HeadingValues nominal_heading_values(const model::VehicleParams& vehicle, const AutopilotSettings& autopilot);

// Rows of the log (indices into row_*) where each link can be scored: the
// servo where m_fin and c_fin are logged under water, the autopilot where
// c_fin is logged under a heading command.
std::vector<std::size_t> servo_rows(const HeadingTrack& track);
std::vector<std::size_t> autopilot_rows(const HeadingTrack& track);

// The times of the law's cycles the log did not hold (between two rows
// cycles_between apart, as the autopilot's replay steps them), sorted.
std::vector<double> unlogged_cycle_times(const HeadingTrack& track);

// Predictions at `rows` / `samples` (sorted); NaN where the model has none.
// The servo's: from the logged commands; at the first row after the command
// of an unlogged cycle (`unlogged`: unlogged_cycle_times) acts, the fin
// followed a command the log does not hold - the prediction there is the
// measured fin and the replay goes on from it, its target there too
// (docs/science.md "The servo after unlogged cycles").
void predict_servo_fin(const HeadingTrack& track, std::span<const double> unlogged, const model::VehicleParams& vehicle,
                       const HeadingValues& values, std::span<const std::size_t> rows, std::vector<double>& out);
void predict_autopilot_fin(const HeadingTrack& track, const AutopilotSettings& settings, const HeadingValues& values,
                           std::span<const std::size_t> rows, std::vector<double>& out);
// predict_autopilot_fin for many values on one track (the fits): what the
// law reads at each row (heading error, heading rate, cycle) depends on the
// autopilot delay alone, so it is worked out once per delay (the last few
// kept) and each call only steps the law - same bits, a fraction of the
// cost (the replay was 2/3 of a heading diagnosis). Holds a reference to
// the track; not for use from two threads at once.
// The clock the law integrates over: each step's own interval (measured,
// the time since the last cycle: this project's firmware) or the log's
// median cycle at every step (nominal: a law written for its cycle time).
// Which one a Slocum's uses is not known (its source is not public; two
// comet logs cannot tell, one prefers the measured: docs/science.md "The
// autopilot's clock").
enum class AutopilotClock : unsigned char { kMeasured, kNominal };

class AutopilotReplay {
 public:
  AutopilotReplay(const HeadingTrack& track, const AutopilotSettings& settings,
                  AutopilotClock clock = AutopilotClock::kMeasured);
  void predict(const HeadingValues& values, std::span<const std::size_t> rows, std::vector<double>& out);

 private:
  // What the law reads for one autopilot delay, as arrays (the replay's
  // loops run down them): per row what it does, and the law's steps in
  // order - a row's unlogged cycles', then its own.
  enum class RowKind : unsigned char { kCentre, kNone, kStep };  // fin centred / no prediction / law steps
  // The integrator after each step for one integral gain (`ki_bits`): where
  // the law cannot hold (no heading deadband) it depends on the delay's
  // steps and that gain alone, so a replay that moves only the gain on the
  // error or the rate (a Jacobian's gain and dgain columns) reuses it.
  // Cleared when its delay's buffers take another delay.
  struct IntegratorSeries {
    bool valid = false;
    std::uint64_t ki_bits = 0;
    std::vector<double> after_step;
  };
  struct Inputs {
    double delay = 0.0;
    std::vector<RowKind> kind;            // per row
    std::vector<std::size_t> step_end;    // per row: one past its last step
    std::vector<double> error, rate, dt;  // per step; the rate +0.0 inside the rate deadband
    std::vector<unsigned char> still;     // per step: the rate inside the rate deadband (AutopilotLaw::step_read)
    std::vector<std::size_t> row;         // per step: the row it predicts (its last step's output stands)
    std::array<IntegratorSeries, 2> integrators;
    std::size_t next_integrator = 0;  // the one the next new gain overwrites
  };
  static constexpr std::size_t kCachedDelays = 4;
  Inputs& inputs(double delay);
  const std::vector<double>& integrator(Inputs& in, double ki);
  const HeadingTrack& track_;
  AutopilotSettings settings_;
  AutopilotClock clock_ = AutopilotClock::kMeasured;
  // The log's cycle and half its jitter's spread: a gap of k cycles is k
  // steps of the law.
  double cycle_s_ = 0.0, half_spread_s_ = 0.0;
  // The depth at which the command changes (a Slocum's new heading at the
  // dive's start, when the climb passes its climb-to depth), bracketed by
  // the changes the log holds between two consecutive cycles, and the way
  // the depth moves through it (-1 rising, +1 sinking, 0: no single depth).
  double change_depth_lo_m_ = 0.0, change_depth_hi_m_ = 0.0;
  int change_direction_ = 0;
  double unlogged_command(std::size_t row, double fraction) const;
  // Per row, whatever the delay: the law steps (a heading command, gliding),
  // the cycles in the gap before it, the span and the heading's step
  // (shorter way round) to the next row.
  std::vector<bool> active_;
  std::vector<int> gap_cycles_;
  std::vector<double> row_span_, heading_step_;
  std::size_t max_steps_ = 0;  // the law's steps if every row stepped
  std::vector<Inputs> cache_;
  // The effects the law reads (AutopilotLaw::from and the delay), and their
  // bits at the last replay, whose predictions predicted_ holds.
  static constexpr std::array<HeadingEffect, 5> kLawEffects = {
      HeadingEffect::kAutopilotGain, HeadingEffect::kAutopilotIntegral, HeadingEffect::kAutopilotDgain,
      HeadingEffect::kAutopilotDelay, HeadingEffect::kAutopilotDeadband};
  std::array<std::uint64_t, kLawEffects.size()> replayed_law_{};
  bool replayed_ = false;
  void replay(const HeadingValues& values);
  std::vector<double> predicted_;
};
// The fast pole the yaw carries (s): the prior's centre (HeadingTrack::
// yaw_fast_pole_s) where a yaw delay is, at most that delay; none without
// one. The yaw-delay effect stands for the yaw's late response - a dead
// time behind a fast pole the log cannot tell apart - so without it the
// nominal yaw stays the vehicle file's first-order one (a pole in the
// nominal moved fits where no delay is: docs/science.md "The yaw's fast
// pole"); at most the delay keeps the response continuous from no delay
// (its lumped lag d + min(d, centre)).
double carried_fast_pole(double prior_centre_s, double yaw_delay_s);
// The fast pole a model of this track carries: the one read beside the lag
// (HeadingTrack::yaw_fast_pole_with_lag_s) where there is one, else
// carried_fast_pole's.
double yaw_fast_pole(const HeadingTrack& track, double yaw_delay_s);

// The roll's turn over the vehicle file's for a lift factor (the
// kLiftFactor rival): the lift force holds the glide, so a lift slope x
// times stronger flies it at ~1/x of the angle of attack the turn goes
// through (the independent truth's alpha_effective, dynamics.cpp).
double roll_turn_per_lift(double lift_factor);

// One step h of the yaw through the fast pole p (HeadingTrack::
// yaw_fast_pole_s; 0: none) and the lag tau, the goal held over it (exact):
// `lead`, the goal as the fast pole passes it, moves toward the goal; the
// yaw rate's change beyond the first-order step toward the goal
// (a = e^{-h/tau}) is returned - what the pole still holds back.
// (b = e^{-h/p}, unused where p <= 0.)
double fast_pole_step(double& lead, double goal, double h, double tau, double p, double a, double b);

// e^{-h/T} for the replays' steps: the full step's worked out once (nearly
// every step is full; the same bits as each step's own), 0 where T <= 0.
class StepDecay {
 public:
  StepDecay(double time_constant, double full_step)
      : time_constant_(time_constant), full_step_(full_step), full_(of(full_step)) {}
  double operator()(double h) const { return h == full_step_ ? full_ : of(h); }

 private:
  double of(double h) const { return time_constant_ > 0.0 ? std::exp(-h / time_constant_) : 0.0; }
  double time_constant_, full_step_, full_;
};

void predict_yaw_rate(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                      std::span<const std::size_t> samples, std::vector<double>& out);

// What the log's heading holds besides the fin's and the roll's yaw: the
// compass's noise and a slow random yaw (the water, a twisted hull) that the
// glider's own autopilot answers with its fin - so the logged fin is
// correlated with both, and an error that compares the yaw rate of the
// logged fin with the measured one reads the fin's authority biased (the
// independent truth's deep logs: 0.29-0.55 for 1; without its random yaw
// 1.05-1.71, without its compass noise 0.16-0.32; docs/science.md).
struct YawNoise {
  double heading_rad = 0.0;        // compass noise, white (the diagnosis's heading_noise_rad)
  double disturbance_rad_s = 0.0;  // the random yaw rate's RMS (first-order Gauss-Markov) ...
  double correlation_s = 30.0;     // ... and its correlation time
};

// The vehicle link's error with that noise modelled (the prediction-error
// method): a Kalman filter per glide on (heading, yaw rate, random yaw), the
// model's yaw driven by the logged fin and roll, predicts each logged heading
// from the readings before it; the error is that one-step innovation per
// second of the step (rad/s, model - measured), white when the model is
// right. The fin acts on the heading only after the servo has moved it, so
// the innovation is independent of the fin that produced it, and the fit of
// the fin's authority is not biased by the loop that chose the fin. NaN at
// each glide's first sample.
void heading_innovations(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                         const YawNoise& noise, std::span<const std::size_t> samples, std::vector<double>& out);

// The noise's sizes that make the innovations at `samples` likeliest
// (Gaussian) with these values: a grid around `start` (its compass noise
// x1/4..x4; the random yaw 1e-4..2e-2 rad/s over 10-300 s; `grid` false:
// from `start` itself), then refined by factors down to 4 %.
double yaw_noise_cost(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                      const YawNoise& noise, std::span<const std::size_t> samples);
// -2 log likelihood (Gaussian) of the heading's innovations at `samples`
// with these values and this noise: what fit_yaw_noise minimises.
double innovations_cost(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                        const YawNoise& noise, std::span<const std::size_t> samples);

YawNoise fit_yaw_noise(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values,
                       const YawNoise& start, std::span<const std::size_t> samples, bool grid = true);

}  // namespace glider::diagnose
