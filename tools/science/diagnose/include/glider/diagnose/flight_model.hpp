// SPDX-License-Identifier: Apache-2.0
#pragma once
// The nominal flight model extended by the effects of the vocabulary
// (docs/model-discrepancy.md): for each steady-glide sample, the steady glide
// at the logged pitch with the net buoyancy of the logged ballast (the
// approach of Merckelbach's gliderflight), through the project's model.
#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "glider/diagnose/observations.hpp"
#include "glider/model/vehicle.hpp"

namespace glider::diagnose {

enum class Effect : int {
  kBuoyancyOffset = 0,
  kDragChange,
  kHullCompressibility,
  kThermalExpansion,
  kVerticalWaterVelocity,
  kWaterDensity,
  kPitchTrimOffset,  // explains the battery position, not the depth rate
  kPumpLag,          // only the dynamic model (turns) can see it
  kLiftChange,       // the lift slope: sets the angle of attack, so the speed along a measured pitch
  kDepthLag,         // the measured depth is late against pitch and ballast (dynamic model: turns)
  kCount
};
constexpr std::size_t kEffectCount = static_cast<std::size_t>(Effect::kCount);

struct EffectInfo {
  const char* id;                       // the vocabulary's id
  const char* unit;                     // of the reported value
  double nominal;                       // the value that means "no effect"
  double scale;                         // typical size, for the optimiser's conditioning
  double plausible_min, plausible_max;  // a fit outside is a model-structure artefact, not this effect
};

// Whether a fitted value is physically possible for the effect.
bool plausible(Effect effect, double value);
const EffectInfo& info(Effect effect);
Effect effect_from_index(std::size_t index);

// Values in the reported units (g, ratio, 1/Pa, 1/K, m/s, kg/m^3, in, s).
using EffectValues = std::array<double, kEffectCount>;
EffectValues nominal_values();

// Vertical water velocity by depth: the water moves in layers (internal
// waves, convection), which a constant cannot tell from a buoyancy offset in
// a symmetric yo (both shift dives and climbs alike); a profile can.
struct VerticalVelocityProfile {
  double bin_m = 10.0;
  double first_m = 0.0;       // top of the first bin
  std::vector<double> w_m_s;  // per bin, + down
  double at(double depth_m) const;
  // The bin holding a depth (clamped to the first and last); w_m_s not empty.
  std::size_t bin(double depth_m) const;
};

// The nominal vehicle with the vehicle effects applied (buoyancy offset,
// drag, hull compressibility and thermal expansion, pitch trim, lift); the water
// effects (vertical velocity, density) belong to the environment.
// The thermal expansion is about the log's own (median) temperature
// `log_temperature_c`: it explains how the volume varies with the water's
// temperature, never a constant that a buoyancy offset already names.
model::VehicleParams apply(model::VehicleParams nominal, const EffectValues& values, double log_temperature_c);

// Whether a model can fly the values at all (positive drag and lift).
bool flyable(const EffectValues& values);

// Density at the deepest sample with a finite density, minus `nominal`
// (the water_density value); NaN if there is none.
double deepest_density_anomaly(std::span<const double> depth_m, std::span<const double> density_kg_m3,
                               double nominal_kg_m3);

// What the diagnosis fits: a model of the depth rate of a log's samples.
class DepthRateModel {
 public:
  virtual ~DepthRateModel() = default;
  // Predicted depth rate (m/s, + down) of the samples; NaN where the model
  // cannot fly one. `use_ctd_density`: water density from the CTD (the
  // water_density effect on a log with CTD data), else nominal + the value.
  // A `profile` replaces the constant vertical velocity value when given.
  virtual void predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                       std::vector<double>& out, const VerticalVelocityProfile* profile = nullptr) const = 0;
  // Density at the deepest CTD sample minus the nominal (the water_density value).
  virtual double ctd_density_anomaly() const = 0;
  // Speed through the water (m/s) at `samples`, as predict() flies them: to
  // score against a measured one (a DVL's), which the fit never sees.
  virtual void predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                             std::vector<double>& out) const = 0;
  // The measured speed through water of every sample (NaN where none).
  virtual std::span<const double> measured_speed_m_s() const = 0;
};

// The steady model: each steady-glide sample is the steady glide at its
// logged pitch (fast; blind to turns and to the pump lag).
class FlightModel final : public DepthRateModel {
 public:
  FlightModel(const model::VehicleParams& nominal, const Observations& observations);

  // NaN where the model has no steady glide (stall).
  void predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
               std::vector<double>& out, const VerticalVelocityProfile* profile = nullptr) const override;
  void predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                     std::vector<double>& out) const override;
  std::span<const double> measured_speed_m_s() const override { return obs_.speed_through_water_m_s; }

  // Pitch of the model's forward equilibrium (logged ballast and battery)
  // for a sample, with the vehicle effects `values` applied; NaN without
  // battery data or a steady glide.
  double equilibrium_pitch_rad(std::size_t sample, const EffectValues& values) const;
  double nominal_pitch_rad(std::size_t sample) const { return equilibrium_pitch_rad(sample, nominal_values()); }

  // The battery position (in) that holds the logged pitch with the logged
  // ballast in a steady glide (moment balance of the model); NaN if none.
  // The vehicle is the nominal one with `values` applied (the effects found).
  // With use_ctd_density, the sample's measured density where it has one
  // (as predict's), else the constant of `values`.
  double required_battpos_in(std::size_t sample, const EffectValues& values, bool use_ctd_density = false) const;

  double ctd_density_anomaly() const override;

  const model::VehicleParams& vehicle() const { return nominal_; }

 private:
  // The steady glide of every sample: its depth rate (+ the water's) or its speed.
  void glide(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
             std::vector<double>& out, const VerticalVelocityProfile* profile, bool speed) const;

  model::VehicleParams nominal_;
  const Observations& obs_;
};

}  // namespace glider::diagnose
