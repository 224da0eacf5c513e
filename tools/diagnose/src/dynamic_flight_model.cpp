// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/dynamic_flight_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <Eigen/Dense>

#include "glider/diagnose/depth_lag.hpp"
#include "glider/model/prescribed_pitch.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double lerp(double a, double b, double f) { return a + (b - a) * f; }

}  // namespace

DynamicFlightModel::DynamicFlightModel(const model::VehicleParams& nominal, const Track& track, double max_step_s)
    : nominal_(nominal),
      track_(track),
      max_step_s_(max_step_s),
      relative_flights_(track.run_first.size()),
      start_states_(track.run_first.size()),
      next_start_(track.run_first.size(), 0) {}

void DynamicFlightModel::predict(const EffectValues& x, bool use_ctd, std::span<const std::size_t> samples,
                                 std::vector<double>& out, const VerticalVelocityProfile* profile) const {
  fly(x, use_ctd, samples, &out, nullptr, profile);
}

void DynamicFlightModel::predict_speed(const EffectValues& x, bool use_ctd, std::span<const std::size_t> samples,
                                       std::vector<double>& out) const {
  fly(x, use_ctd, samples, nullptr, &out, nullptr);
}

void DynamicFlightModel::fly(const EffectValues& x, bool use_ctd, std::span<const std::size_t> samples,
                             std::vector<double>* depth_rate, std::vector<double>* speed,
                             const VerticalVelocityProfile* profile) const {
  const bool memo = samples.size() <= kFlightMemoSamples;
  // Bit for bit (-0.0 is not +0.0 here): the same question, so the same answer.
  auto same_bits = [](std::span<const double> a, std::span<const double> b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
  };
  auto same_question = [&](const FlightAnswer& a) {
    return same_bits(a.values, x) && a.use_ctd == use_ctd && a.depth_rate == (depth_rate != nullptr) &&
           a.speed == (speed != nullptr) && a.has_profile == (profile != nullptr) &&
           (profile == nullptr || (same_bits(std::span(&a.profile.bin_m, 1), std::span(&profile->bin_m, 1)) &&
                                   same_bits(std::span(&a.profile.first_m, 1), std::span(&profile->first_m, 1)) &&
                                   same_bits(a.profile.w_m_s, profile->w_m_s))) &&
           std::equal(a.samples.begin(), a.samples.end(), samples.begin(), samples.end());
  };
  if (memo) {
    for (const FlightAnswer& a : answers_) {
      if (!same_question(a)) continue;
      if (depth_rate != nullptr) *depth_rate = a.depth_rate_out;
      if (speed != nullptr) *speed = a.speed_out;
      return;
    }
  }
  fly_uncached(x, use_ctd, samples, depth_rate, speed, profile);
  if (!memo) return;
  if (answers_.size() < kFlightMemo) answers_.emplace_back();
  FlightAnswer& a = answers_[next_answer_];
  next_answer_ = (next_answer_ + 1) % kFlightMemo;
  a.values = x;
  a.use_ctd = use_ctd;
  a.depth_rate = depth_rate != nullptr;
  a.speed = speed != nullptr;
  a.has_profile = profile != nullptr;
  if (profile != nullptr) a.profile = *profile;
  a.samples.assign(samples.begin(), samples.end());
  if (depth_rate != nullptr) a.depth_rate_out = *depth_rate;
  if (speed != nullptr) a.speed_out = *speed;
}

void DynamicFlightModel::fly_uncached(const EffectValues& x, bool use_ctd, std::span<const std::size_t> samples,
                                      std::vector<double>* depth_rate, std::vector<double>* speed,
                                      const VerticalVelocityProfile* profile) const {
  if (depth_rate != nullptr) depth_rate->assign(samples.size(), kNaN);
  if (speed != nullptr) speed->assign(samples.size(), kNaN);
  if (!flyable(x)) return;  // no negative drag or lift
  const model::VehicleParams v = apply(nominal_, x, track_.median_temperature_c);
  const model::PrescribedPitchDynamics dynamics(v);
  const double lag_s = v.ballast.lag_s;
  const double constant_density = v.trim_density_kg_m3 + x[static_cast<std::size_t>(Effect::kWaterDensity)];
  const double constant_w = x[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)];
  const double depth_lag_s = std::abs(x[static_cast<std::size_t>(Effect::kDepthLag)]);  // no sign, as the pump's
  const Track& t = track_;
  auto water_w = [&](double depth) { return profile != nullptr ? profile->at(depth) : constant_w; };
  auto density = [&](std::size_t k) {
    return use_ctd && std::isfinite(t.density_kg_m3[k]) ? t.density_kg_m3[k] : constant_density;
  };
  auto temperature = [&](std::size_t k) {
    return std::isfinite(t.temperature_c[k]) ? t.temperature_c[k] : v.hull_reference_temperature_c;
  };
  auto battery = [&](std::size_t k) { return std::isfinite(t.battpos_in[k]) ? in_to_m(t.battpos_in[k]) : 0.0; };

  std::size_t next = 0;  // next requested sample
  for (std::size_t run = 0; run < t.run_first.size() && next < samples.size(); ++run) {
    const std::size_t first = t.run_first[run];
    const std::size_t end = t.run_end(run);
    if (samples[next] >= end) continue;  // nothing requested in this run (every sample is in a run)
    // Inputs at fraction f of the interval [i, i + 1], with the displaced
    // volume lagged from `lagged0` at the interval's start fraction f0.
    auto inputs = [&](std::size_t i, double f, double lagged0, double f0) {
      const std::size_t j = i + 1 < end ? i + 1 : i;
      model::PrescribedPitchInputs in;
      const double dt = j > i ? t.time_s[j] - t.time_s[i] : 0.0;
      // Pitch and its rate on the cubic Hermite through the samples.
      const double f2 = f * f, f3 = f2 * f;
      in.theta_rad = (2.0 * f3 - 3.0 * f2 + 1.0) * t.pitch_rad[i] + (f3 - 2.0 * f2 + f) * dt * t.pitch_slope_rad_s[i] +
                     (-2.0 * f3 + 3.0 * f2) * t.pitch_rad[j] + (f3 - f2) * dt * t.pitch_slope_rad_s[j];
      in.q_rad_s = dt > 0.0 ? ((6.0 * f2 - 6.0 * f) * (t.pitch_rad[i] - t.pitch_rad[j]) / dt +
                               (3.0 * f2 - 4.0 * f + 1.0) * t.pitch_slope_rad_s[i] +
                               (3.0 * f2 - 2.0 * f) * t.pitch_slope_rad_s[j])
                            : t.pitch_slope_rad_s[i];
      in.depth_m = lerp(t.depth_m[i], t.depth_m[j], f);
      in.battery_pos_m = lerp(battery(i), battery(j), f);
      in.density_kg_m3 = lerp(density(i), density(j), f);
      in.temperature_c = lerp(temperature(i), temperature(j), f);
      // The ballast as the pump moved it (pump_ramp.hpp), lagged exactly.
      in.pumped_volume_m3 = cc_to_m3(
          lag_over_ramp(m3_to_cc(lagged0), t.ballast_cc[i], t.ballast_cc[j], t.ballast_ramp[i], f0, f, dt, lag_s));
      return in;
    };
    model::PrescribedPitchInputs in0 = inputs(first, 0.0, cc_to_m3(t.ballast_cc[first]), 0.0);
    using Impulse = model::PrescribedPitchDynamics::Impulse;  // not auto: Eigen expressions would dangle
    using Derivative = model::PrescribedPitchDynamics::Derivative;
    // The depth rate over ground (the water's own vertical velocity added).

    // Flies the run from its first sample with body velocities (v1, v3) up
    // to sample `last`: the model's depth change through the water at each
    // sample into rel (0 at the first), its speed into u when asked. Returns
    // the last sample reached with a finite state. The water's own vertical
    // velocity moves the glider without changing its flight through the
    // water: ground_depth adds it (the start state aside, which the spin-up
    // fits on the depth over ground, a flight does not depend on it).
    auto fly_run = [&](double v1, double v3, std::size_t last, std::vector<double>& z, std::vector<double>* u) {
      Impulse p = dynamics.impulse(v1, v3, in0);
      double lagged = in0.pumped_volume_m3;
      z.assign(last - first + 1, kNaN);
      if (u != nullptr) u->assign(last - first + 1, kNaN);
      z[0] = 0.0;
      if (u != nullptr) (*u)[0] = dynamics.velocities(p, in0).norm();
      std::size_t flown = first;
      for (std::size_t i = first; i < last; ++i) {
        const double dt = t.time_s[i + 1] - t.time_s[i];
        const int steps = std::max(1, static_cast<int>(std::ceil(dt / max_step_s_ - 1e-9)));
        const double h = dt / steps;
        double depth = z[i - first];
        for (int s = 0; s < steps; ++s) {
          const double fa = static_cast<double>(s) / steps;
          const double fb = (s + 0.5) / steps;
          const double fc = static_cast<double>(s + 1) / steps;
          const auto a = inputs(i, fa, lagged, fa);
          const auto b = inputs(i, fb, lagged, fa);
          const auto c = inputs(i, fc, lagged, fa);
          const Derivative d1 = dynamics.derivative(p, a);
          const Impulse p2 = p + 0.5 * h * d1.p_dot;
          const Derivative d2 = dynamics.derivative(p2, b);
          const Impulse p3 = p + 0.5 * h * d2.p_dot;
          const Derivative d3 = dynamics.derivative(p3, b);
          const Impulse p4 = p + h * d3.p_dot;
          const Derivative d4 = dynamics.derivative(p4, c);
          depth +=
              h / 6.0 * (d1.depth_rate_m_s + 2.0 * d2.depth_rate_m_s + 2.0 * d3.depth_rate_m_s + d4.depth_rate_m_s);
          p += h / 6.0 * (d1.p_dot + 2.0 * d2.p_dot + 2.0 * d3.p_dot + d4.p_dot);
          lagged = c.pumped_volume_m3;
        }
        if (!p.allFinite() || !std::isfinite(depth)) break;  // the rest of the run stays NaN: unflyable
        z[i + 1 - first] = depth;
        if (u != nullptr) (*u)[i + 1 - first] = dynamics.velocities(p, inputs(i, 1.0, lagged, 1.0)).norm();
        flown = i + 1;
      }
      return flown;
    };
    // The depth over ground at samples first..flown: the measured first
    // depth, the flight's relative depth `rel` and the water's vertical
    // velocity integrated with the same RK4 weights at the same stages.
    auto ground_depth = [&](std::size_t flown, const std::vector<double>& rel, std::vector<double>& z) {
      z.assign(rel.size(), kNaN);
      z[0] = t.depth_m[first] + rel[0];
      double water = 0.0;
      for (std::size_t i = first; i < flown; ++i) {
        const double dt = t.time_s[i + 1] - t.time_s[i];
        const int steps = std::max(1, static_cast<int>(std::ceil(dt / max_step_s_ - 1e-9)));
        const double h = dt / steps;
        for (int s = 0; s < steps; ++s) {
          const double wa = water_w(lerp(t.depth_m[i], t.depth_m[i + 1], static_cast<double>(s) / steps));
          const double wb = water_w(lerp(t.depth_m[i], t.depth_m[i + 1], (s + 0.5) / steps));
          const double wc = water_w(lerp(t.depth_m[i], t.depth_m[i + 1], static_cast<double>(s + 1) / steps));
          water += h / 6.0 * (wa + 2.0 * wb + 2.0 * wb + wc);
        }
        z[i + 1 - first] = t.depth_m[first] + rel[i + 1 - first] + water;
      }
    };
    // The start. A run begins where the glider leaves the surface or a gap,
    // far from a steady glide: leaving the surface it sinks at a large angle
    // of attack and takes a minute or two to reach its glide (surge is
    // slow). Started on the steady glide, the model dives too fast for that
    // long, in the warm top layer, and a fit reads it as buoyancy that
    // follows temperature (+5.5e-6 /K of thermal expansion on clean SIL
    // data). So the two body velocities at the start are nuisance
    // parameters, fitted (Gauss-Newton) to the measured depth over the
    // spin-up, which is never scored; the guess is the steady glide at the
    // first pitch, scaled to the measured depth rate.
    double v1 = 0.0, v3 = 0.0;
    // The start state depends on the values (the depth lag aside), the
    // density source and the water's profile only: a run's last few are
    // remembered (about a third of the start fits of a real log's diagnosis
    // repeat one: the Jacobian's depth-lag column, a refit), the same bits.
    EffectValues start_key = x;
    start_key[static_cast<std::size_t>(Effect::kDepthLag)] = 0.0;
    std::vector<StartState>& starts = start_states_[run];
    auto same_start = [&](const StartState& s) {
      return std::memcmp(s.values.data(), start_key.data(), sizeof start_key) == 0 && s.use_ctd == use_ctd &&
             s.has_profile == (profile != nullptr) &&
             (profile == nullptr || (s.profile.bin_m == profile->bin_m && s.profile.first_m == profile->first_m &&
                                     s.profile.w_m_s.size() == profile->w_m_s.size() &&
                                     std::memcmp(s.profile.w_m_s.data(), profile->w_m_s.data(),
                                                 sizeof(double) * profile->w_m_s.size()) == 0));
    };
    const auto known = std::find_if(starts.begin(), starts.end(), same_start);
    if (known != starts.end()) {
      v1 = known->v1;
      v3 = known->v3;
    } else {
      const auto steady =
          model::steady_glide_for_pitch(v.hydro, in0.density_kg_m3, in0.theta_rad, dynamics.net_buoyancy_kg(in0));
      if (steady.glide) {
        v1 = steady.glide->speed_m_s * std::cos(steady.glide->alpha_rad);
        v3 = steady.glide->speed_m_s * std::sin(steady.glide->alpha_rad);
        const double steady_rate = dynamics.depth_rate_m_s(dynamics.impulse(v1, v3, in0), in0);
        const double measured_rate = t.depth_rate_m_s[first] - water_w(in0.depth_m);
        if (std::abs(steady_rate) > 1e-3 && std::isfinite(measured_rate)) {
          const double scale = std::clamp(measured_rate / steady_rate, 0.0, 1.5);
          v1 *= scale;
          v3 *= scale;
        }
      }
      std::size_t fit_last = first;
      while (fit_last + 1 < end && t.time_s[fit_last + 1] - t.time_s[first] <= t.spin_up_s) ++fit_last;
      if (fit_last >= first + 3) {
        const std::size_t n = fit_last - first;
        std::vector<double>& zf = fit_buffer_;
        std::vector<double>& rel = fit_relative_buffer_;
        auto misfit = [&](double a, double b, Eigen::VectorXd& r) {
          if (fly_run(a, b, fit_last, rel, nullptr) != fit_last) return false;
          // Not through the depth lag: the start state is a nuisance fitted on
          // a part never scored, and without the lag it stays the same for
          // every lag, so a depth_lag fit reuses the flight (only the depth
          // over ground is read late again).
          ground_depth(fit_last, rel, zf);
          r.resize(static_cast<Eigen::Index>(n));
          for (std::size_t k = 1; k <= n; ++k) r[static_cast<Eigen::Index>(k - 1)] = zf[k] - t.depth_m[first + k];
          return true;
        };
        // Chord method: the depth over half a minute is nearly linear in the
        // start velocities, so the Jacobian at the guess serves every step
        // (each step then costs one flight of the spin-up, not three).
        Eigen::VectorXd r, r_trial, r_a, r_b;
        constexpr double kDelta = 1e-4;  // m/s, finite-difference step
        if (misfit(v1, v3, r) && misfit(v1 + kDelta, v3, r_a) && misfit(v1, v3 + kDelta, r_b)) {
          Eigen::MatrixXd jac(r.size(), 2);
          jac.col(0) = (r_a - r) / kDelta;
          jac.col(1) = (r_b - r) / kDelta;
          const Eigen::Matrix2d normal = jac.transpose() * jac + 1e-9 * Eigen::Matrix2d::Identity();
          const auto solver = normal.ldlt();
          for (int iteration = 0; iteration < 8; ++iteration) {
            Eigen::Vector2d step = solver.solve(-jac.transpose() * r);
            if (!step.allFinite()) break;
            double taken = 0.0;  // length of the step taken (halved until the misfit does not grow)
            for (int halving = 0; halving < 4 && taken == 0.0; ++halving) {
              const double a = std::clamp(v1 + step[0], -1.5, 1.5), b = std::clamp(v3 + step[1], -1.5, 1.5);
              if (misfit(a, b, r_trial) && r_trial.squaredNorm() <= r.squaredNorm()) {
                v1 = a;
                v3 = b;
                r.swap(r_trial);
                taken = step.norm() + 1e-300;
              }
              step *= 0.5;
            }
            if (taken < 1e-6) break;  // converged, or no step helps
          }
        }
      }
      if (starts.size() < kStartStates) starts.emplace_back();
      StartState& slot = starts[next_start_[run]];
      next_start_[run] = (next_start_[run] + 1) % kStartStates;
      slot = {start_key, use_ctd, profile != nullptr, profile != nullptr ? *profile : VerticalVelocityProfile{},
              v1,        v3};
    }
    // Fly up to the last requested sample of this run and on through its
    // estimator window (the slope at a sample uses the samples after it),
    // and at least one sample further: a centred difference (no window, or
    // none after the sample within it) needs the next sample. A prediction
    // then never depends on which other samples are asked for.
    // The model's depth is integrated with the same RK4 weights, so that its
    // depth rate can go through the very estimator the measurement went
    // through (the track's windowed slope): like is compared with like, also
    // in turns, where a +-5 s slope is not the instantaneous rate.
    std::size_t last_needed = std::min(end - 1, samples.back());
    const double window_end_s = t.time_s[last_needed] + t.rate_half_window_s;
    if (last_needed + 1 < end) ++last_needed;
    while (last_needed + 1 < end && t.time_s[last_needed + 1] <= window_end_s) ++last_needed;
    // The flight through the water is reused when only the water's
    // velocity changed and the start state came out the same (a profile
    // bin the run's spin-up does not reach: the Jacobian of a depth
    // profile costs a flight per bin otherwise).
    RelativeFlight& flight = relative_flights_[run];
    EffectValues key = x;
    key[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)] = 0.0;
    key[static_cast<std::size_t>(Effect::kDepthLag)] = 0.0;  // the sensor's, not the flight's
    const bool reuse = flight.valid && flight.key == key && flight.use_ctd == use_ctd && flight.v1 == v1 &&
                       flight.v3 == v3 && flight.last >= last_needed && (speed == nullptr || flight.has_speed);
    if (!reuse) {
      flight.flown = fly_run(v1, v3, last_needed, flight.depth, speed != nullptr ? &flight.speed : nullptr);
      flight = {true,
                key,
                use_ctd,
                v1,
                v3,
                last_needed,
                flight.flown,
                speed != nullptr,
                std::move(flight.depth),
                std::move(flight.speed)};
    }
    const std::size_t flown = std::min(flight.flown, last_needed);
    const std::vector<double>& u = flight.speed;
    std::vector<double>& z = depth_buffer_;
    ground_depth(flown, flight.depth, z);
    const std::size_t count = flown - first + 1;
    const std::span<const double> time = std::span(t.time_s).subspan(first, count);
    delay_depth(time, std::span(z).first(count), depth_lag_s);  // as the sensor read it
    const std::span<const double> depth = std::span<const double>(z).first(count);
    // The estimator at the requested samples only (a stride of the run's);
    // the whole column where a depth is not finite (its gaps rule differs).
    const bool finite = std::all_of(depth.begin(), depth.end(), [](double d) { return std::isfinite(d); });
    const flightlog::Column column =
        finite ? flightlog::Column{} : depth_rate_estimate(time, depth, t.rate_half_window_s, t.max_gap_s);
    for (; next < samples.size() && samples[next] < end; ++next) {
      const std::size_t k = samples[next];
      if (k > flown) continue;
      if (depth_rate != nullptr) {
        (*depth_rate)[next] = finite ? depth_rate_estimate_at(time, depth, k - first, t.rate_half_window_s, t.max_gap_s)
                                     : column[k - first];
      }
      if (speed != nullptr) (*speed)[next] = u[k - first];
    }
  }
}

double DynamicFlightModel::ctd_density_anomaly() const {
  return deepest_density_anomaly(track_.depth_m, track_.density_kg_m3, nominal_.trim_density_kg_m3);
}

}  // namespace glider::diagnose
