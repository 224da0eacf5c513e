#include "glider/diagnose/dynamic_flight_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "glider/model/first_order_lag.hpp"
#include "glider/model/prescribed_pitch.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double lerp(double a, double b, double f) { return a + (b - a) * f; }

}  // namespace

DynamicFlightModel::DynamicFlightModel(const model::VehicleParams& nominal, const Track& track, double max_step_s)
    : nominal_(nominal), track_(track), max_step_s_(max_step_s) {}

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
  if (depth_rate != nullptr) depth_rate->assign(samples.size(), kNaN);
  if (speed != nullptr) speed->assign(samples.size(), kNaN);
  if (!(x[static_cast<std::size_t>(Effect::kDragChange)] > 0.0)) return;  // no negative drag
  const model::VehicleParams v = apply(nominal_, x);
  const model::PrescribedPitchDynamics dynamics(v);
  const double lag_s = v.ballast.lag_s;
  const double constant_density = v.trim_density_kg_m3 + x[static_cast<std::size_t>(Effect::kWaterDensity)];
  const double constant_w = x[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)];
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
    while (next < samples.size() && samples[next] < first) ++next;  // left behind by a failed run
    if (next == samples.size() || samples[next] >= end) continue;   // nothing requested in this run
    // Inputs at fraction f of the interval [i, i + 1], with the displaced
    // volume lagged from `lagged0` at the interval's start fraction f0.
    auto inputs = [&](std::size_t i, double f, double q, double lagged0, double f0) {
      const std::size_t j = i + 1 < end ? i + 1 : i;
      model::PrescribedPitchInputs in;
      in.theta_rad = lerp(t.pitch_rad[i], t.pitch_rad[j], f);
      in.q_rad_s = q;
      in.depth_m = lerp(t.depth_m[i], t.depth_m[j], f);
      in.battery_pos_m = lerp(battery(i), battery(j), f);
      in.density_kg_m3 = lerp(density(i), density(j), f);
      in.temperature_c = lerp(temperature(i), temperature(j), f);
      const double dt = j > i ? t.time_s[j] - t.time_s[i] : 0.0;
      const double u0 = cc_to_m3(lerp(t.ballast_cc[i], t.ballast_cc[j], f0));
      const double u1 = cc_to_m3(lerp(t.ballast_cc[i], t.ballast_cc[j], f));
      in.pumped_volume_m3 = model::first_order_lag_after(lagged0, u0, u1, (f - f0) * dt, lag_s);
      return in;
    };
    model::PrescribedPitchInputs in0 = inputs(first, 0.0, 0.0, cc_to_m3(t.ballast_cc[first]), 0.0);
    double lagged = in0.pumped_volume_m3;
    // Start in the steady glide at the first pitch, else at rest (the
    // track's spin-up keeps the start's transient out of the score).
    const auto start = model::steady_glide_for_pitch(v.hydro, in0.density_kg_m3, in0.theta_rad,
                                                     dynamics.net_buoyancy_kg(in0));
    const double v1 = start.glide ? start.glide->speed_m_s * std::cos(start.glide->alpha_rad) : 0.0;
    const double v3 = start.glide ? start.glide->speed_m_s * std::sin(start.glide->alpha_rad) : 0.0;
    model::PrescribedPitchDynamics::Impulse p = dynamics.impulse(v1, v3, in0);
    auto record = [&](std::size_t k, const model::PrescribedPitchInputs& in) {
      while (next < samples.size() && samples[next] < k) ++next;
      if (next < samples.size() && samples[next] == k) {
        if (depth_rate != nullptr) (*depth_rate)[next] = dynamics.depth_rate_m_s(p, in) + water_w(t.depth_m[k]);
        if (speed != nullptr) (*speed)[next] = dynamics.velocities(p, in).norm();
        ++next;
      }
    };
    record(first, in0);
    for (std::size_t i = first; i + 1 < end && next < samples.size(); ++i) {
      const double dt = t.time_s[i + 1] - t.time_s[i];
      const int steps = std::max(1, static_cast<int>(std::ceil(dt / max_step_s_ - 1e-9)));
      const double h = dt / steps;
      const double q = dt > 0.0 ? (t.pitch_rad[i + 1] - t.pitch_rad[i]) / dt : 0.0;
      for (int s = 0; s < steps; ++s) {
        const double fa = static_cast<double>(s) / steps;
        const double fb = (s + 0.5) / steps;
        const double fc = static_cast<double>(s + 1) / steps;
        const auto a = inputs(i, fa, q, lagged, fa);
        const auto b = inputs(i, fb, q, lagged, fa);
        const auto c = inputs(i, fc, q, lagged, fa);
        const auto k1 = dynamics.rate(p, a);
        const auto k2 = dynamics.rate(p + 0.5 * h * k1, b);
        const auto k3 = dynamics.rate(p + 0.5 * h * k2, b);
        const auto k4 = dynamics.rate(p + h * k3, c);
        p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        if (!p.allFinite()) return;  // the rest stays NaN: counted as unflyable
        lagged = c.pumped_volume_m3;
      }
      record(i + 1, inputs(i, 1.0, q, lagged, 1.0));
    }
  }
}

double DynamicFlightModel::ctd_density_anomaly() const {
  return deepest_density_anomaly(track_.depth_m, track_.density_kg_m3, nominal_.trim_density_kg_m3);
}

}  // namespace glider::diagnose
