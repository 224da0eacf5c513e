// SPDX-License-Identifier: Apache-2.0
#pragma once
// The dynamic flight model of the diagnosis: the project's vertical-plane
// dynamics with the measured pitch prescribed (model/prescribed_pitch.hpp),
// flown through every run of the log with the logged ballast (through the
// pump lag) and battery, from the start state that flies each run's spin-up
// (never scored) closest to the measured depth. It predicts the
// depth rate of every sample, turns included, which the steady model cannot:
// that is where a pump lag shows ("the model turns earlier than the glider").
#include <span>
#include <vector>

#include "glider/diagnose/flight_model.hpp"
#include "glider/diagnose/track.hpp"

namespace glider::diagnose {

class DynamicFlightModel final : public DepthRateModel {
 public:
  // Integration step: at most max_step_s (RK4); the log's cycles are split
  // into equal sub-steps.
  DynamicFlightModel(const model::VehicleParams& nominal, const Track& track, double max_step_s = 1.0);

  // Depth rate (m/s, + down) at `samples` (indices into the track, sorted);
  // only the runs that hold them are flown.
  void predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
               std::vector<double>& out, const VerticalVelocityProfile* profile = nullptr) const override;

  void predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                     std::vector<double>& out) const override;
  std::span<const double> measured_speed_m_s() const override { return track_.speed_through_water_m_s; }

  // Density at the deepest CTD sample of the track minus the nominal.
  double ctd_density_anomaly() const override;

 private:
  void fly(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
           std::vector<double>* depth_rate, std::vector<double>* speed, const VerticalVelocityProfile* profile) const;

  model::VehicleParams nominal_;
  const Track& track_;
  double max_step_s_;
  mutable std::vector<double> depth_buffer_, fit_buffer_, fit_relative_buffer_;  // per run, reused across calls
  // Each run's last flight through the water (relative depth and speed),
  // for the effect values but the water's vertical velocity, from (v1, v3).
  struct RelativeFlight {
    bool valid = false;
    EffectValues key{};
    bool use_ctd = false;
    double v1 = 0.0, v3 = 0.0;
    std::size_t last = 0, flown = 0;
    bool has_speed = false;
    std::vector<double> depth, speed;
  };
  mutable std::vector<RelativeFlight> relative_flights_;
};

}  // namespace glider::diagnose
