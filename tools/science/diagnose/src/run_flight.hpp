// SPDX-License-Identifier: Apache-2.0
#pragma once
// One flight of the diagnosis's dynamic model through one run of the track
// (from the surface or a gap to the next): the inputs between the log's
// samples, the RK4 integration of the prescribed-pitch dynamics, the depth
// over ground, and the start state fitted on the run's spin-up.
// dynamic_flight_model.cpp decides which runs to fly and what to remember.
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "glider/diagnose/flight_model.hpp"
#include "glider/diagnose/track.hpp"
#include "glider/model/prescribed_pitch.hpp"

namespace glider::diagnose::detail {

// Sub-steps of RK4 between samples i and i + 1: equal, at most max_step_s.
int rk4_steps(double dt, double max_step_s);

// The pitch at every stage of every RK4 step through the track (the cubic
// Hermite through the samples), its rate, sine and cosine. They are the
// track's alone, the same for every flight of a diagnosis (hundreds), so
// they are computed once per track: the same expressions on the same
// numbers, so the same bits (a sincos and a Hermite per stage were a tenth
// of a diagnosis's CPU). Stage k of interval [i, i + 1] with n sub-steps is
// at the fraction stage_fraction(k, n): k = 2s the start of sub-step s,
// 2s + 1 its middle, 2n the end.
class StagePitchTable {
 public:
  struct Pitch {
    double theta_rad, q_rad_s, sin_theta, cos_theta;
  };
  StagePitchTable(const Track& track, double max_step_s);
  const Pitch& at(std::size_t i, int k) const { return pitch_[offset_[i] + static_cast<std::size_t>(k)]; }
  // rk4_steps of interval [i, i + 1] (i + 1 a sample of the track): its
  // 2 steps + 1 stages here. Looked up, not worked out again (a ceil and a
  // division at every interval of every flight, 2 % of a 24 h log).
  int steps(std::size_t i) const { return static_cast<int>((offset_[i + 1] - offset_[i]) / 2); }

 private:
  std::vector<std::size_t> offset_;  // per interval i, its stage 0
  std::vector<Pitch> pitch_;
};

// The fraction of its interval at which stage k of n sub-steps lies.
inline double stage_fraction(int k, int n) { return k % 2 == 0 ? static_cast<double>(k / 2) / n : (k / 2 + 0.5) / n; }

// What every run of one flight shares: the vehicle with the effect values,
// its dynamics, the water and the integration step.
class FlightConditions {
 public:
  FlightConditions(const model::VehicleParams& nominal, const EffectValues& x, bool use_ctd, const Track& track,
                   const VerticalVelocityProfile* profile, double max_step_s, const StagePitchTable& pitch);
  FlightConditions(const FlightConditions&) = delete;  // `dynamics` was made from `vehicle`
  FlightConditions& operator=(const FlightConditions&) = delete;

  // What a run's stage inputs depend on besides the track (RunFlight::inputs):
  // the density source, the density where none is logged, the hull's
  // reference temperature and the pump's lag. Compared bit for bit.
  struct InputKey {
    double use_ctd, constant_density, hull_reference_temperature_c, pump_lag_s;
  };
  InputKey input_key() const {
    return {use_ctd_ ? 1.0 : 0.0, constant_density_, vehicle.hull_reference_temperature_c, vehicle.ballast.lag_s};
  }

  // The water's own vertical velocity at a depth (m/s, + down).
  double water_w(double depth_m) const { return profile_ != nullptr ? profile_->at(depth_m) : constant_w_; }
  bool has_profile() const { return profile_ != nullptr; }
  const VerticalVelocityProfile* profile() const { return profile_; }
  // The water of these conditions is `profile` (or the constant `w` without
  // one), bit for bit.
  bool same_water(bool has_profile, double w, const VerticalVelocityProfile& profile) const;
  void water_of(bool& has_profile, double& w, VerticalVelocityProfile& profile) const;
  // Sample k's density (the CTD's where asked for and logged), temperature and battery position.
  double density(std::size_t k) const;
  double temperature(std::size_t k) const;
  double battery(std::size_t k) const;

  const Track& track;
  const model::VehicleParams vehicle;
  const model::PrescribedPitchDynamics dynamics;
  const double max_step_s;
  const StagePitchTable& pitch;

 private:
  const bool use_ctd_;
  const double constant_density_, constant_w_;
  const VerticalVelocityProfile* profile_;
};

// A run's stage inputs (three a RK4 step: its start, middle and end) as
// the first flight under the same input key computed them: they depend on
// that key and the track alone, never on the start state nor on the other
// effect values, and a diagnosis flies a run hundreds of times (the
// start-state fit's 4-35 flights of the spin-up, then every fit's Jacobian
// column of an effect that leaves them alone). The same values read back:
// the same bits. Filled in order from the run's first sample.
struct RunStages {
  bool valid = false;
  FlightConditions::InputKey key{};
  std::vector<model::PrescribedPitchInputs> stages;
  std::size_t intervals = 0;  // the intervals filled so far
  // Of those, the first `pumped` hold the pumped volume of the key's pump
  // lag: a new lag alone (the pump lag's grid, fit and Jacobian: a new one
  // at every flight) recomputes only the pumped volumes (RunFlight::
  // refresh_pumped), the rest of a stage's inputs do not depend on it.
  std::size_t pumped = 0;
  // The water's vertical displacement after each interval (ground_depth),
  // for the water it was integrated in: its own key.
  bool water_valid = false, water_has_profile = false;
  double water_w = 0.0;
  VerticalVelocityProfile water_profile;
  std::vector<double> water;
  // The profile's bin at each of ground_depth's stages (three a step), for
  // the profile's geometry (first_m, bin_m, bins; bit for bit): a depth
  // profile's Jacobian asks one geometry with a new velocity per bin, and
  // each is integrated over the whole run. Filled in order, per interval.
  double bins_first_m = 0.0, bins_bin_m = 0.0;
  std::size_t bins_count = 0;
  std::vector<std::size_t> bins_offset;  // per interval filled, its first stage in `bins`
  std::vector<std::uint32_t> bins;
};

// Where the start-state fit's flight from the fitted start state stood at
// the spin-up's last sample: its impulses, its skin-friction anchors and its
// relative depth at each sample so far. A main flight from that start state
// goes on from there (RunFlight::fly_runs) instead of flying the spin-up
// again: the same stages in the same order, so the same bits.
struct SpinUpEnd {
  model::PrescribedPitchDynamics::Impulse p = model::PrescribedPitchDynamics::Impulse::Zero();
  std::optional<model::SkinFrictionFactor> friction;  // empty: nothing to go on from
  std::vector<double> rel;
};

// A main flight's trace (RunFlight::fly_runs), for a later main flight of
// the same run, flight key and density source (the same vehicle, the same
// stage inputs) from another start state: the flight is damped, so the two
// come to the same impulses and skin-friction anchors bit for bit, in the
// 24 h SIL log after 800 of its 85,000 samples (a water velocity's Jacobian
// column or a new velocity moves the start state, not the flight's key). From
// there the later flight's every step is the traced one's, so it takes the
// traced depth increments instead of flying them: the same sums in the same
// order onto its own depth, the same bits.
struct FlightTrace {
  // Where the traced flight stood after closing sample first + kEvery * m
  // (empty before it was flown there: a flight on from the spin-up's end).
  static constexpr std::size_t kEvery = 16;
  struct Checkpoint {
    model::PrescribedPitchDynamics::Impulse p;
    model::SkinFrictionFactor friction;
  };
  std::vector<std::optional<Checkpoint>> checkpoints;
  std::vector<double> increments;  // each RK4 step's depth increment, by step (its first stage / 3)
  std::size_t last = 0;            // the sample the trace reaches (0: none)
  std::size_t joined_at = 0;       // the sample where this flight joined another's (0: flown throughout)
};

class RunFlight {
 public:
  // The run of samples [first, end); `stages` is kept by the caller between
  // flights of the run (reset here where the conditions' input key differs).
  RunFlight(const FlightConditions& c, std::size_t first, std::size_t end, RunStages& stages);

  std::size_t first() const { return first_; }
  std::size_t end() const { return end_; }

  // Inputs at stage k of the interval [i, i + 1] (of n sub-steps:
  // StagePitchTable), with the displaced volume lagged from `lagged0` at
  // the interval's stage k0.
  model::PrescribedPitchInputs inputs(std::size_t i, int k, int n, double lagged0, int k0) const;
  // Its pumped volume alone (inputs() takes it from here).
  double pumped_volume_m3(std::size_t i, int k, int n, double lagged0, int k0) const;

  // Flies the run from its first sample with body velocities (v1, v3) up
  // to sample `last`: the model's depth change through the water at each
  // sample into z (0 at the first), its speed into u when asked. Returns
  // the last sample reached with a finite state. The water's own vertical
  // velocity moves the glider without changing its flight through the
  // water: ground_depth adds it.
  //
  // stop_above (finite): the flight stops as soon as the running sum of
  // its squared depth misfits (depth over ground minus measured, samples
  // first + 1 on) exceeds it, returning a sample before `last`. Needs the
  // water's displacement up to `last` kept (ground_depth ran that far).
  std::size_t fly(double v1, double v3, std::size_t last, std::vector<double>& z, std::vector<double>* u,
                  double stop_above = std::numeric_limits<double>::infinity()) const;

  // What fly_runs's steps read of a run: its times, first sample, step and cached stages.
  struct StagesView {
    const std::vector<double>& time_s;
    std::size_t first;
    const StagePitchTable& pitch;
    const model::PrescribedPitchInputs* stages;
  };

  // Computes the stages fly() would up to `last` into the run's cache
  // (RunStages), in order from the first not cached, without flying: the
  // same calls on the same numbers, so the same bits.
  void cache_stages(std::size_t last) const;
  // Brings the cached stages' pumped volumes up to `last` to this flight's
  // pump lag (RunStages::pumped), as cache_stages would compute them.
  void refresh_pumped(std::size_t last) const;

  // N runs' flights side by side, each exactly run->fly(v1, v3, last, *z,
  // nullptr) (the same bits): a main flight is one long chain of dependent
  // operations per stage (a division, a square root, the skin friction's
  // series, atan2) that leaves the core mostly idle, and other runs' fill
  // it. Every run's stages must be cached up to its `last`
  // (cache_stages); no speeds, no misfit bound. The flights after the
  // first get their own copy of the dynamics (its stage cache). Returns
  // each flight's last sample reached. `from` (optional, its friction
  // set): the flight goes on from the spin-up's end, (v1, v3) the start
  // state the fit flew it from.
  struct RunQuestion {
    const RunFlight* run;
    double v1, v3;
    std::size_t last;
    std::vector<double>* z;
    const SpinUpEnd* from = nullptr;
    // This flight's own trace (null: none kept), and another's of the same
    // run, flight key and density source to join where their states meet
    // (null: none); not the same object.
    FlightTrace* trace = nullptr;
    const FlightTrace* join = nullptr;
  };
  template <std::size_t N>
  static std::array<std::size_t, N> fly_runs(const std::array<RunQuestion, N>& q);

  // The depth over ground at samples first..flown: the measured first
  // depth, the flight's relative depth `rel` and the water's vertical
  // velocity integrated with the same RK4 weights at the same stages.
  void ground_depth(std::size_t flown, const std::vector<double>& rel, std::vector<double>& z) const;

  // The start state (body velocities) that flies the spin-up closest to
  // the measured depth, from the steady glide at the first pitch scaled to
  // the measured depth rate. `z` and `rel` are work buffers. `end`: where
  // the flight from the fitted start state stood at the spin-up's last
  // sample (its friction left empty where none flew there).
  void fit_start(double& v1, double& v3, std::vector<double>& z, std::vector<double>& rel, SpinUpEnd& end) const;
  // All of the water fit_start reads: its vertical displacement after each
  // of the spin-up's intervals (as ground_depth integrates it; kept in the
  // run's RunStages) and its velocity at the first depth (the guess's).
  // The same bits here, the same start state from the same values.
  struct SpinUpWater {
    std::span<const double> displacement;
    double start_w;
  };
  SpinUpWater spin_up_water() const;

 private:
  void guess_start(double& v1, double& v3) const;
  // The water's vertical displacement after each interval up to sample
  // `flown` into RunStages::water (in order; those kept are not integrated again).
  void integrate_water(std::size_t flown) const;
  // N flights of fly() side by side through the same stages (each its own
  // start, z and stop_above; speeds u of the first only), each the same bits
  // as flown alone: a stage is a chain of dependent operations (a division,
  // a square root, the skin friction's series, atan2) that leaves the core
  // mostly idle, and independent flights fill it. Returns each flight's
  // last sample reached.
  // ends (optional): where each flight that reached `last` stood there
  // (the others' friction left as it was).
  template <std::size_t N>
  std::array<std::size_t, N> fly_n(const std::array<double, N>& v1, const std::array<double, N>& v3, std::size_t last,
                                   const std::array<std::vector<double>*, N>& z, std::vector<double>* u,
                                   const std::array<double, N>& stop_above,
                                   std::array<SpinUpEnd, N>* ends = nullptr) const;
  // Whether the profile's bins are kept (RunStages::bins; a profile with
  // bins), for its geometry: once per ground_depth.
  bool bins_kept() const;
  // The profile's bin at ground_depth's three stages a step of interval i
  // (RunStages::bins, bins_kept()), or nullptr where they are not kept.
  const std::uint32_t* stage_bins(std::size_t i, int steps) const;
  StagesView view() const { return {t_.time_s, first_, c_.pitch, stages_.stages.data()}; }

  const FlightConditions& c_;
  const Track& t_;
  std::size_t first_, end_;
  model::PrescribedPitchInputs in0_;
  // The spin-up's last sample (the start-state fit flies [first_, spin_up_last_]).
  std::size_t spin_up_last_;
  std::size_t spin_up_stage_ = 0;  // the first of RunStages::stages after it
  RunStages& stages_;
};

}  // namespace glider::diagnose::detail
