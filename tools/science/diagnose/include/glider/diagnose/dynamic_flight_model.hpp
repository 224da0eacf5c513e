// SPDX-License-Identifier: Apache-2.0
#pragma once
// The dynamic flight model of the diagnosis: the project's vertical-plane
// dynamics with the measured pitch prescribed (model/prescribed_pitch.hpp),
// flown through every run of the log with the logged ballast (through the
// pump lag) and battery, from the start state that flies each run's spin-up
// (never scored) closest to the measured depth. It predicts the
// depth rate of every sample, turns included, which the steady model cannot:
// that is where a pump lag shows ("the model turns earlier than the glider").
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "glider/diagnose/depth_lag.hpp"
#include "glider/diagnose/flight_model.hpp"
#include "glider/diagnose/track.hpp"

namespace glider::diagnose {

namespace detail {
class RunFlight;        // one run's flight (src/run_flight.hpp)
class StagePitchTable;  // the track's pitch at every RK4 stage (src/run_flight.hpp)
struct RunStages;       // a run's stage inputs, kept between its flights (src/run_flight.hpp)
struct SpinUpEnd;       // where a flight stands at the spin-up's end (src/run_flight.hpp)
struct FlightTrace;     // a main flight's states and depth increments (src/run_flight.hpp)
}  // namespace detail

class DynamicFlightModel final : public DepthRateModel {
 public:
  // Integration step: at most max_step_s (RK4); the log's cycles are split
  // into equal sub-steps.
  // Runs of at least traced_samples samples keep their main flights'
  // traces, for later flights from another start state to join (run_flight.hpp's
  // FlightTrace; the same bits either way).
  static constexpr std::size_t kTracedSamples = 1000;
  DynamicFlightModel(const model::VehicleParams& nominal, const Track& track, double max_step_s = 1.0,
                     std::size_t traced_samples = kTracedSamples);
  ~DynamicFlightModel() override;

  // Depth rate (m/s, + down) at `samples` (indices into the track, sorted);
  // only the runs that hold them are flown. The depth is read late by the
  // depth lag (|value|) in `depth_lag_form` (depth_lag.hpp); predict()
  // without it reads a delay. Every flight is shared by the two forms (a
  // flight does not depend on the depth lag); their answers are not.
  void predict(const EffectValues& values, DepthLagForm depth_lag_form, bool use_ctd_density,
               std::span<const std::size_t> samples, std::vector<double>& out,
               const VerticalVelocityProfile* profile = nullptr) const;
  void predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
               std::vector<double>& out, const VerticalVelocityProfile* profile = nullptr) const override;

  void predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                     std::vector<double>& out) const override;
  std::span<const double> measured_speed_m_s() const override { return track_.speed_through_water_m_s; }

  // Density at the deepest CTD sample of the track minus the nominal.
  double ctd_density_anomaly() const override;

  // Main flights that joined a traced one (FlightTrace) so far.
  std::size_t joined_flights() const { return joined_flights_; }

 private:
  void fly(const EffectValues& values, DepthLagForm depth_lag_form, bool use_ctd_density,
           std::span<const std::size_t> samples, std::vector<double>* depth_rate, std::vector<double>* speed,
           const VerticalVelocityProfile* profile) const;
  void fly_uncached(const EffectValues& values, DepthLagForm depth_lag_form, bool use_ctd_density,
                    std::span<const std::size_t> samples, std::vector<double>* depth_rate, std::vector<double>* speed,
                    const VerticalVelocityProfile* profile) const;

  struct RelativeFlight;
  std::size_t last_needed(std::size_t end, std::size_t last_requested) const;
  // The run's start state into (v1, v3), and where its flight stands at the
  // spin-up's end (kept here, or in `own`: null where there is none).
  const detail::SpinUpEnd* start_state(const detail::RunFlight& run_flight, std::size_t run, const EffectValues& values,
                                       bool use_ctd, double& v1, double& v3, detail::SpinUpEnd& own) const;
  const RelativeFlight* kept_flight(std::size_t run, const EffectValues& key, bool use_ctd, double v1, double v3,
                                    std::size_t last, bool with_speed) const;
  RelativeFlight& flight_slot(std::size_t run) const;
  const detail::FlightTrace* joinable_trace(std::size_t run, const EffectValues& key, bool use_ctd,
                                            const RelativeFlight& slot) const;
  static EffectValues flight_key(const EffectValues& x);
  std::size_t read_run(const detail::RunFlight& run_flight, const RelativeFlight& flight, std::size_t last,
                       DepthLagForm depth_lag_form, double depth_lag_s, std::span<const std::size_t> samples,
                       std::size_t next, std::vector<double>* depth_rate, std::vector<double>* speed) const;

  model::VehicleParams nominal_;
  const Track& track_;
  double max_step_s_;
  std::unique_ptr<const detail::StagePitchTable> stage_pitch_;  // the track's pitch at every stage (run_flight.hpp)
  mutable std::vector<double> depth_buffer_, fit_buffer_, fit_relative_buffer_;  // per run, reused across calls
  // A run's flight through the water (relative depth and speed), for the
  // effect values but the water's vertical velocity, from (v1, v3).
  struct RelativeFlight {
    bool valid = false;
    EffectValues key{};
    bool use_ctd = false;
    double v1 = 0.0, v3 = 0.0;
    std::size_t last = 0, flown = 0;
    bool has_speed = false;
    std::vector<double> depth, speed;
    // Its trace (FlightTrace::last 0: none, a flight with speeds), for a
    // later flight of the same key and density source from another start
    // state to join (joinable_trace).
    std::unique_ptr<detail::FlightTrace> trace;
  };
  // A run's last kRelativeFlights flights (round robin): an LM Jacobian's
  // columns alternate between effects that change the flight and ones that
  // do not (the water's velocity, the depth lag), so the flight of the
  // column before the last is often the one asked again.
  static constexpr std::size_t kRelativeFlights = 8;
  struct RunRelativeFlights {
    std::vector<RelativeFlight> flights;
    std::size_t next = 0;  // the slot the next flight replaces
  };
  mutable std::vector<RunRelativeFlights> relative_flights_;
  // Each run's start states (the body velocities fitted on its spin-up) by
  // what they depend on: the values but the depth lag and the water's
  // velocity, the density source, and the water as the spin-up meets it
  // (its vertical displacement after each of the spin-up's intervals and
  // its velocity at the first depth: RunFlight::spin_up_water). A depth
  // profile's bins the spin-up never reaches leave that water the same bits,
  // so a profile's Jacobian column of such a bin is no new start fit (a
  // quarter of comet-2016's start fits). Up to kStartStateBytes of them
  // (comet-2016's diagnosis fits ~21000, ~15000 of them different): a start
  // state is a function of that key alone (a flight's bits are its
  // question's, run_flight.hpp), so a remembered one is the one the fit
  // would give again. Keyed by a hash of the key's bits, compared bit for bit.
  struct StartState {
    EffectValues values{};
    bool use_ctd = false;
    double start_w = 0.0;
    std::vector<double> water;
    double v1 = 0.0, v3 = 0.0;
    std::unique_ptr<detail::SpinUpEnd> end;  // where the flight from (v1, v3) stands at the spin-up's end
  };
  static constexpr std::size_t kStartStateBytes = std::size_t{48} << 20;
  mutable std::vector<std::unordered_multimap<std::uint64_t, StartState>> start_states_;
  mutable std::size_t start_state_bytes_ = 0;
  mutable std::vector<detail::RunStages> run_stages_;  // per run
  // The flights' answers, by their whole question: a selection asks the same
  // values at the same samples again (a fit's start point, a refit of a set
  // already fitted, an interval's profile), and a flight is a deterministic
  // function of them, so the answer is the same bits (docs/science.md,
  // speed). Kept up to kFlightMemoBytes of answers (then no more are added),
  // none for requests of more than kFlightMemoSamples samples.
  struct FlightAnswer {
    EffectValues values{};
    DepthLagForm depth_lag_form = DepthLagForm::kDelay;
    bool use_ctd = false, has_profile = false, depth_rate = false, speed = false;
    VerticalVelocityProfile profile;
    std::vector<std::size_t> samples;
    std::vector<double> depth_rate_out, speed_out;
  };
  static constexpr std::size_t kFlightMemoBytes = std::size_t{64} << 20, kFlightMemoSamples = 20000;
  mutable std::unordered_multimap<std::uint64_t, FlightAnswer> answers_;
  mutable std::size_t answer_bytes_ = 0;
  std::size_t traced_samples_;
  mutable std::size_t joined_flights_ = 0;
};

// A dynamic flight model read with the depth lag in one form: what a fit
// asks, as a DepthRateModel. Both views may sit on one model (its flights
// shared). Each asks with the depth lag's magnitude (fitted as |value|, as
// the pump's), so the optimiser's two signs of a lag share an answer.
class DepthLagView final : public DepthRateModel {
 public:
  DepthLagView(const DynamicFlightModel& model, DepthLagForm form) : model_(model), form_(form) {}
  DepthLagForm form() const { return form_; }
  void predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
               std::vector<double>& out, const VerticalVelocityProfile* profile = nullptr) const override;
  void predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                     std::vector<double>& out) const override;
  double ctd_density_anomaly() const override { return model_.ctd_density_anomaly(); }
  std::span<const double> measured_speed_m_s() const override { return model_.measured_speed_m_s(); }

 private:
  const DynamicFlightModel& model_;
  DepthLagForm form_;
};

}  // namespace glider::diagnose
