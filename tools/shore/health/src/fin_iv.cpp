// SPDX-License-Identifier: Apache-2.0
#include "glider/health/fin_iv.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "glider/diagnose/heading_diagnose.hpp"
#include "glider/diagnose/heading_models.hpp"
#include "glider/diagnose/heading_track.hpp"
#include "glider/fitting_core/intervals.hpp"

namespace glider::health {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;
using diagnose::HeadingEffect;
using diagnose::HeadingValues;

// The two values solved for, in this order.
constexpr std::array<HeadingEffect, 2> kSolved = {HeadingEffect::kFinEffectiveness, HeadingEffect::kRollOffset};
// Finite-difference steps of the sensitivities: the model is linear in the
// fin's effectiveness and smooth in the roll offset (its sine).
constexpr std::array<double, 2> kStep = {1e-3, 1e-4};
// Gauss-Newton rounds on the moment condition; it is linear in the fin, so
// two already agree to ~1e-9.
constexpr int kRounds = 4;
constexpr double kSettled = 1e-7;
// At least this many glides (clusters) for a covariance.
constexpr std::size_t kMinGlides = 3;

struct Model {
  const diagnose::HeadingTrack& track;
  const model::VehicleParams& vehicle;
  std::vector<double> out;
  // The model's yaw rate at `samples` with `values`, as an Eigen vector.
  Eigen::VectorXd rate(const HeadingValues& values, const std::vector<std::size_t>& samples) {
    diagnose::predict_yaw_rate(track, vehicle, values, samples, out);
    return Eigen::Map<const Eigen::VectorXd>(out.data(), static_cast<Eigen::Index>(out.size()));
  }
  // d rate / d (fin effectiveness, roll offset), by central differences.
  Eigen::MatrixXd sensitivities(const HeadingValues& values, const std::vector<std::size_t>& samples) {
    Eigen::MatrixXd s(static_cast<Eigen::Index>(samples.size()), 2);
    for (std::size_t j = 0; j < kSolved.size(); ++j) {
      HeadingValues up = values, down = values;
      diagnose::at(up, kSolved[j]) += kStep[j];
      diagnose::at(down, kSolved[j]) -= kStep[j];
      s.col(static_cast<Eigen::Index>(j)) = (rate(up, samples) - rate(down, samples)) / (2.0 * kStep[j]);
    }
    return s;
  }
};

}  // namespace

FinByInstruments fin_by_instruments(const model::VehicleParams& vehicle, const flightlog::FlightLog& logged,
                                    bool stored_on_change, const flightlog::FlightLog& projected) {
  diagnose::HeadingTrackOptions logged_options;
  logged_options.fin_stored_on_change = stored_on_change;
  const diagnose::HeadingTrack track = diagnose::prepare_heading_track(logged, vehicle, logged_options);
  // The projection is defined at every row: not read as stored on change.
  const diagnose::HeadingTrack instrument_track = diagnose::prepare_heading_track(projected, vehicle, {});

  // The samples both tracks score at the same time, with a measured and a
  // modelled rate (a row is a glide sample only where its fin is defined,
  // and the projection is defined at rows the file did not store the fin).
  const HeadingValues nominal = diagnose::nominal_heading_values(vehicle, diagnose::configured_autopilot(logged));
  Model logged_model{track, vehicle, {}};
  Model instrument_model{instrument_track, vehicle, {}};
  std::vector<std::size_t> samples, instrument_samples;
  {
    const Eigen::VectorXd rate = logged_model.rate(nominal, track.scored);
    const Eigen::VectorXd instrument = instrument_model.rate(nominal, instrument_track.scored);
    std::size_t j = 0;
    for (std::size_t k = 0; k < track.scored.size(); ++k) {
      const std::size_t i = track.scored[k];
      while (j < instrument_track.scored.size() &&
             instrument_track.time_s[instrument_track.scored[j]] < track.time_s[i]) {
        ++j;
      }
      if (j == instrument_track.scored.size()) break;
      if (instrument_track.time_s[instrument_track.scored[j]] != track.time_s[i]) continue;
      if (std::isfinite(rate(static_cast<Eigen::Index>(k))) &&
          std::isfinite(instrument(static_cast<Eigen::Index>(j))) && std::isfinite(track.yaw_rate_rad_s[i])) {
        samples.push_back(i);
        instrument_samples.push_back(instrument_track.scored[j]);
      }
    }
  }
  Eigen::VectorXd measured(static_cast<Eigen::Index>(samples.size()));
  for (std::size_t k = 0; k < samples.size(); ++k)
    measured(static_cast<Eigen::Index>(k)) = track.yaw_rate_rad_s[samples[k]];

  // Solve W' e = 0 by Gauss-Newton: values -= (W' J)^-1 W' e.
  HeadingValues values = nominal;
  Eigen::VectorXd error;
  Eigen::MatrixXd jac, instruments;
  for (int round = 0; round < kRounds; ++round) {
    error = logged_model.rate(values, samples) - measured;
    jac = logged_model.sensitivities(values, samples);
    instruments = instrument_model.sensitivities(values, instrument_samples);
    const Eigen::Vector2d step = (instruments.transpose() * jac).fullPivLu().solve(instruments.transpose() * error);
    if (!step.allFinite()) throw std::runtime_error(logged.source() + ": the fin's instruments are singular");
    for (std::size_t j = 0; j < kSolved.size(); ++j)
      diagnose::at(values, kSolved[j]) -= step(static_cast<Eigen::Index>(j));
    if (step.cwiseAbs().maxCoeff() < kSettled) break;
  }
  error = logged_model.rate(values, samples) - measured;
  jac = logged_model.sensitivities(values, samples);
  instruments = instrument_model.sensitivities(values, instrument_samples);

  // The interval by fitting_core's rule for the heading fit (kGlides): the
  // wider of the lag-1 one (the noise over the residuals' effective sample
  // count) and the cluster-robust one (each glide a cluster, Student's t on
  // G - 1), each in its instrumental-variables form: with A = W' J,
  //   lag-1:   A^-1 (W'W) [(W'W)^-1 s^2 n / n_eff] (W'W) A^-T,
  //   cluster: A^-1 [sum_g (W_g' e_g)(W_g' e_g)'] A^-T G/(G-1) (n-1)/(n-k).
  std::vector<Eigen::Vector2d> scores(track.run_first.size(), Eigen::Vector2d::Zero());
  std::size_t run = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    while (samples[k] >= track.run_end(run)) ++run;
    scores[run] += instruments.row(static_cast<Eigen::Index>(k)).transpose() * error(static_cast<Eigen::Index>(k));
  }
  Eigen::Matrix2d meat = Eigen::Matrix2d::Zero();
  std::size_t glides = 0;
  for (const Eigen::Vector2d& s : scores) {
    if (s.isZero(0.0)) continue;
    meat += s * s.transpose();
    ++glides;
  }
  if (glides < kMinGlides) {
    throw std::runtime_error(logged.source() + ": " + std::to_string(glides) + " glides with yaw samples, at least " +
                             std::to_string(kMinGlides) + " needed for the fin's interval");
  }
  const auto n = static_cast<double>(samples.size());
  const auto g = static_cast<double>(glides);
  const Eigen::Matrix2d bread = (instruments.transpose() * jac).inverse();
  const Eigen::Matrix2d clustered =
      bread * meat * bread.transpose() * (g / (g - 1.0)) * ((n - 1.0) / (n - static_cast<double>(kSolved.size())));
  const Eigen::Matrix2d gram = instruments.transpose() * instruments;
  const Eigen::Matrix2d lag1 =
      bread * gram *
      fitting_core::noise_covariance(instruments, std::span<const double>(error.data(), samples.size())) * gram *
      bread.transpose();
  const double t_over_normal = fitting_core::t_quantile_975(g - 1.0) / fitting_core::kZ95;
  const auto half_width = [&](Eigen::Index j) {
    return fitting_core::kZ95 * std::max(std::sqrt(lag1(j, j)), t_over_normal * std::sqrt(clustered(j, j)));
  };

  FinByInstruments result;
  result.glides = glides;
  const double fin = diagnose::at(values, HeadingEffect::kFinEffectiveness);
  const double fin_half = half_width(0);
  result.fin = {fin, fin - fin_half, fin + fin_half, {}};
  const double roll =
      (track.roll_logged ? track.median_roll_rad : 0.0) + diagnose::at(values, HeadingEffect::kRollOffset);
  const double roll_half = half_width(1);
  result.roll_deg = {roll * kDeg, (roll - roll_half) * kDeg, (roll + roll_half) * kDeg, {}};
  return result;
}

}  // namespace glider::health
