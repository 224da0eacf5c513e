// SPDX-License-Identifier: Apache-2.0
#include "run_flight.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

#include <Eigen/Dense>

#include "glider/diagnose/pump_ramp.hpp"
#include "glider/model/steady_glide.hpp"
#include "glider/units.hpp"

namespace glider::diagnose::detail {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The start-state fit's step halvings, and how many of their trials fly
// side by side (RunFlight::fit_start).
constexpr std::size_t kHalvings = 4;
constexpr std::size_t kTrialsTogether = 2;

double lerp(double a, double b, double f) { return a + (b - a) * f; }

using Impulse = model::PrescribedPitchDynamics::Impulse;  // not auto: Eigen expressions would dangle
using Derivative = model::PrescribedPitchDynamics::Derivative;

}  // namespace

StagePitchTable::StagePitchTable(const Track& t, double max_step_s) {
  const std::size_t n = t.time_s.size();
  offset_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    offset_.push_back(pitch_.size());
    // The last sample of the track (and of each run) is its own interval's
    // end: its one stage is the sample (inputs() takes j = i there).
    const std::size_t j = i + 1 < n ? i + 1 : i;
    const double dt = j > i ? t.time_s[j] - t.time_s[i] : 0.0;
    const int steps = rk4_steps(dt, max_step_s);
    for (int k = 0; k <= 2 * steps; ++k) {
      const double f = stage_fraction(k, steps);
      // Pitch and its rate on the cubic Hermite through the samples.
      const double f2 = f * f, f3 = f2 * f;
      const double theta = (2.0 * f3 - 3.0 * f2 + 1.0) * t.pitch_rad[i] +
                           (f3 - 2.0 * f2 + f) * dt * t.pitch_slope_rad_s[i] + (-2.0 * f3 + 3.0 * f2) * t.pitch_rad[j] +
                           (f3 - f2) * dt * t.pitch_slope_rad_s[j];
      const double q = dt > 0.0 ? ((6.0 * f2 - 6.0 * f) * (t.pitch_rad[i] - t.pitch_rad[j]) / dt +
                                   (3.0 * f2 - 4.0 * f + 1.0) * t.pitch_slope_rad_s[i] +
                                   (3.0 * f2 - 2.0 * f) * t.pitch_slope_rad_s[j])
                                : t.pitch_slope_rad_s[i];
      pitch_.push_back({theta, q, std::sin(theta), std::cos(theta)});
    }
  }
}

FlightConditions::FlightConditions(const model::VehicleParams& nominal, const EffectValues& x, bool use_ctd,
                                   const Track& t, const VerticalVelocityProfile* profile, double max_step,
                                   const StagePitchTable& stage_pitch)
    : track(t),
      vehicle(apply(nominal, x, t.median_temperature_c)),
      dynamics(vehicle),
      max_step_s(max_step),
      pitch(stage_pitch),
      use_ctd_(use_ctd),
      constant_density_(vehicle.trim_density_kg_m3 + x[static_cast<std::size_t>(Effect::kWaterDensity)]),
      constant_w_(x[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)]),
      profile_(profile) {}

bool FlightConditions::same_water(bool has_profile, double w, const VerticalVelocityProfile& profile) const {
  auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  if (has_profile != (profile_ != nullptr)) return false;
  if (profile_ == nullptr) return same(w, constant_w_);
  return same(profile.bin_m, profile_->bin_m) && same(profile.first_m, profile_->first_m) &&
         profile.w_m_s.size() == profile_->w_m_s.size() &&
         (profile.w_m_s.empty() ||
          std::memcmp(profile.w_m_s.data(), profile_->w_m_s.data(), sizeof(double) * profile.w_m_s.size()) == 0);
}

void FlightConditions::water_of(bool& has_profile, double& w, VerticalVelocityProfile& profile) const {
  has_profile = profile_ != nullptr;
  w = constant_w_;
  profile = profile_ != nullptr ? *profile_ : VerticalVelocityProfile{};
}

double FlightConditions::density(std::size_t k) const {
  return use_ctd_ && std::isfinite(track.density_kg_m3[k]) ? track.density_kg_m3[k] : constant_density_;
}

double FlightConditions::temperature(std::size_t k) const {
  return std::isfinite(track.temperature_c[k]) ? track.temperature_c[k] : vehicle.hull_reference_temperature_c;
}

double FlightConditions::battery(std::size_t k) const {
  return std::isfinite(track.battpos_in[k]) ? in_to_m(track.battpos_in[k]) : 0.0;
}

int rk4_steps(double dt, double max_step_s) { return std::max(1, static_cast<int>(std::ceil(dt / max_step_s - 1e-9))); }

RunFlight::RunFlight(const FlightConditions& c, std::size_t first, std::size_t end, RunStages& stages)
    : c_(c), t_(c.track), first_(first), end_(end), spin_up_last_(first), stages_(stages) {
  const FlightConditions::InputKey key = c.input_key();
  if (!stages_.valid || std::memcmp(&stages_.key, &key, sizeof key) != 0) {
    FlightConditions::InputKey but_lag = key;
    but_lag.pump_lag_s = stages_.key.pump_lag_s;
    if (stages_.valid && std::memcmp(&stages_.key, &but_lag, sizeof key) == 0) {
      stages_.pumped = 0;  // the pump lag alone changed: its volumes only (refresh_pumped)
    } else {
      stages_.valid = true;
      stages_.stages.clear();
      stages_.intervals = 0;
      stages_.pumped = 0;
    }
    stages_.key = key;
  }
  if (!stages_.water_valid || !c.same_water(stages_.water_has_profile, stages_.water_w, stages_.water_profile)) {
    stages_.water_valid = true;
    c.water_of(stages_.water_has_profile, stages_.water_w, stages_.water_profile);
    stages_.water.clear();
  }
  in0_ = inputs(first, 0, 1, cc_to_m3(t_.ballast_cc[first]), 0);
  while (spin_up_last_ + 1 < end_ && t_.time_s[spin_up_last_ + 1] - t_.time_s[first_] <= t_.spin_up_s) ++spin_up_last_;
  for (std::size_t i = first_; i < spin_up_last_; ++i)
    spin_up_stage_ += 3 * static_cast<std::size_t>(c_.pitch.steps(i));
}

model::PrescribedPitchInputs RunFlight::inputs(std::size_t i, int k, int n, double lagged0, int k0) const {
  const Track& t = t_;
  const std::size_t j = i + 1 < end_ ? i + 1 : i;
  model::PrescribedPitchInputs in;
  const double f = stage_fraction(k, n);
  // The pitch from the track's table where its interval is this one (the
  // run's last sample is the table's only where the track ends there).
  if (j == i + 1 || i + 1 == t.time_s.size()) {
    const StagePitchTable::Pitch& p = c_.pitch.at(i, j > i ? k : 0);
    in.theta_rad = p.theta_rad;
    in.q_rad_s = p.q_rad_s;
    in.sin_theta = p.sin_theta;
    in.cos_theta = p.cos_theta;
  } else {  // a run's last sample before the next run: its interval's end is itself
    in.theta_rad = t.pitch_rad[i];
    in.q_rad_s = t.pitch_slope_rad_s[i];
  }
  in.depth_m = lerp(t.depth_m[i], t.depth_m[j], f);
  in.battery_pos_m = lerp(c_.battery(i), c_.battery(j), f);
  in.density_kg_m3 = lerp(c_.density(i), c_.density(j), f);
  in.temperature_c = lerp(c_.temperature(i), c_.temperature(j), f);
  in.pumped_volume_m3 = pumped_volume_m3(i, k, n, lagged0, k0);
  return in;
}

double RunFlight::pumped_volume_m3(std::size_t i, int k, int n, double lagged0, int k0) const {
  const Track& t = t_;
  const std::size_t j = i + 1 < end_ ? i + 1 : i;
  const double dt = j > i ? t.time_s[j] - t.time_s[i] : 0.0;
  const double f = stage_fraction(k, n), f0 = stage_fraction(k0, n);
  // The ballast as the pump moved it (pump_ramp.hpp), lagged exactly.
  return cc_to_m3(lag_over_ramp(m3_to_cc(lagged0), t.ballast_cc[i], t.ballast_cc[j], t.ballast_ramp[i], f0, f, dt,
                                c_.vehicle.ballast.lag_s));
}

void RunFlight::refresh_pumped(std::size_t last) const {
  const std::size_t upto = std::min(stages_.intervals, last > first_ ? last - first_ : 0);
  if (stages_.pumped >= upto) return;
  // The stages are three a sub-step, in order: the first stage of interval `pumped`.
  std::size_t stage = 0;
  for (std::size_t i = first_; i < first_ + stages_.pumped; ++i)
    stage += 3 * static_cast<std::size_t>(c_.pitch.steps(i));
  // The pumped volume lagged from the last refreshed stage's, as cache_stages carries it.
  double lagged = stage == 0 ? in0_.pumped_volume_m3 : stages_.stages[stage - 1].pumped_volume_m3;
  for (std::size_t i = first_ + stages_.pumped; i < first_ + upto; ++i) {
    const int steps = c_.pitch.steps(i);
    for (int s = 0; s < steps; ++s) {
      for (int k = 0; k < 3; ++k)
        stages_.stages[stage + static_cast<std::size_t>(k)].pumped_volume_m3 =
            pumped_volume_m3(i, 2 * s + k, steps, lagged, 2 * s);
      lagged = stages_.stages[stage + 2].pumped_volume_m3;
      stage += 3;
    }
  }
  stages_.pumped = upto;
}

std::size_t RunFlight::fly(double v1, double v3, std::size_t last, std::vector<double>& z, std::vector<double>* u,
                           double stop_above) const {
  return fly_n<1>({v1}, {v3}, last, {&z}, u, {stop_above})[0];
}

template <std::size_t N>
std::array<std::size_t, N> RunFlight::fly_n(const std::array<double, N>& v1, const std::array<double, N>& v3,
                                            std::size_t last, const std::array<std::vector<double>*, N>& z,
                                            std::vector<double>* u, const std::array<double, N>& stop_above,
                                            std::array<SpinUpEnd, N>* ends) const {
  const model::PrescribedPitchDynamics& dynamics = c_.dynamics;
  refresh_pumped(last);  // the cached stages it reads, for this flight's pump lag
  // Each flight's own skin-friction anchors, fresh: a function of its (v1, v3) and the run alone, whatever flew
  // before or beside it.
  const auto friction = [&]<std::size_t... K>(std::index_sequence<K...>) {
    return std::array<model::SkinFrictionFactor, N>{((void)K, dynamics.skin_friction())...};
  }
  (std::make_index_sequence<N>{});
  std::array<Impulse, N> p;
  std::array<double, N> depth{}, misfit{};  // misfit: the running sum of squares, when bounded
  std::array<bool, N> flying{}, bounded{};
  std::array<std::size_t, N> flown{};
  for (std::size_t k = 0; k < N; ++k) {
    p[k] = dynamics.impulse(v1[k], v3[k], in0_);
    z[k]->assign(last - first_ + 1, kNaN);
    (*z[k])[0] = 0.0;
    flying[k] = true;
    bounded[k] = stop_above[k] < std::numeric_limits<double>::infinity();
    flown[k] = first_;
  }
  if (u != nullptr) u->assign(last - first_ + 1, kNaN);
  if (u != nullptr) (*u)[0] = dynamics.velocities(p[0], in0_).norm();
  double lagged = in0_.pumped_volume_m3;
  std::size_t stage = 0;                         // next of stages_.stages
  const Derivative kIdle{Impulse::Zero(), 0.0};  // a flight that stopped
  for (std::size_t i = first_; i < last; ++i) {
    if (std::none_of(flying.begin(), flying.end(), [](bool f) { return f; })) break;
    const double dt = t_.time_s[i + 1] - t_.time_s[i];
    const int steps = c_.pitch.steps(i);
    const double h = dt / steps;
    for (std::size_t k = 0; k < N; ++k) depth[k] = (*z[k])[i - first_];
    // The intervals are cached in order: the first not cached is the next to cache.
    const bool cached = i - first_ < stages_.intervals;
    for (int s = 0; s < steps; ++s) {
      if (!cached) {
        const model::PrescribedPitchInputs a = inputs(i, 2 * s, steps, lagged, 2 * s);
        const model::PrescribedPitchInputs b = inputs(i, 2 * s + 1, steps, lagged, 2 * s);
        const model::PrescribedPitchInputs c = inputs(i, 2 * s + 2, steps, lagged, 2 * s);
        stages_.stages.insert(stages_.stages.end(), {a, b, c});
      }
      const model::PrescribedPitchInputs* stages = &stages_.stages[stage];
      stage += 3;
      const model::PrescribedPitchInputs& a = stages[0];
      const model::PrescribedPitchInputs& b = stages[1];
      const model::PrescribedPitchInputs& c = stages[2];
      // RK4, stage by stage across the flights (the masses of a stage's
      // inputs are computed once for them all: PrescribedPitchDynamics
      // keeps the last inputs').
      std::array<Derivative, N> d1, d2, d3, d4;
      for (std::size_t k = 0; k < N; ++k) d1[k] = flying[k] ? dynamics.derivative(p[k], a, friction[k]) : kIdle;
      for (std::size_t k = 0; k < N; ++k)
        d2[k] = flying[k] ? dynamics.derivative(Impulse(p[k] + 0.5 * h * d1[k].p_dot), b, friction[k]) : kIdle;
      for (std::size_t k = 0; k < N; ++k)
        d3[k] = flying[k] ? dynamics.derivative(Impulse(p[k] + 0.5 * h * d2[k].p_dot), b, friction[k]) : kIdle;
      for (std::size_t k = 0; k < N; ++k)
        d4[k] = flying[k] ? dynamics.derivative(Impulse(p[k] + h * d3[k].p_dot), c, friction[k]) : kIdle;
      for (std::size_t k = 0; k < N; ++k) {
        if (!flying[k]) continue;
        depth[k] +=
            h / 6.0 *
            (d1[k].depth_rate_m_s + 2.0 * d2[k].depth_rate_m_s + 2.0 * d3[k].depth_rate_m_s + d4[k].depth_rate_m_s);
        p[k] += h / 6.0 * (d1[k].p_dot + 2.0 * d2[k].p_dot + 2.0 * d3[k].p_dot + d4[k].p_dot);
      }
      lagged = c.pumped_volume_m3;
    }
    if (!cached) stages_.pumped = ++stages_.intervals;  // refreshed up to here, so the new one too
    for (std::size_t k = 0; k < N; ++k) {
      if (!flying[k]) continue;
      if (!p[k].allFinite() || !std::isfinite(depth[k])) {  // the rest of the run stays NaN: unflyable
        flying[k] = false;
        continue;
      }
      (*z[k])[i + 1 - first_] = depth[k];
      if (bounded[k] && i - first_ < stages_.water.size()) {
        // The misfit as fit_start's residual has it (ground_depth's sum, the same expression).
        const double r = t_.depth_m[first_] + depth[k] + stages_.water[i - first_] - t_.depth_m[i + 1];
        misfit[k] += r * r;
        if (misfit[k] > stop_above[k]) {  // short of `last`: the caller's "worse"
          flown[k] = i + 1;
          flying[k] = false;
          continue;
        }
      }
      flown[k] = i + 1;
    }
    if (u != nullptr && flying[0])
      (*u)[i + 1 - first_] = dynamics.velocities(p[0], inputs(i, 2 * steps, steps, lagged, 2 * steps)).norm();
  }
  for (std::size_t k = 0; k < N && ends != nullptr; ++k) {
    (*ends)[k].friction.reset();
    if (!flying[k] || flown[k] != last) continue;
    (*ends)[k].p = p[k];
    (*ends)[k].friction.emplace(friction[k]);
  }
  return flown;
}

namespace {

// Compared bit for bit as a whole (FlightTrace): its coefficients and anchors, doubles without padding.
static_assert(std::is_trivially_copyable_v<model::SkinFrictionFactor> &&
              sizeof(model::SkinFrictionFactor) == 8 * sizeof(double));

// One flight of fly_runs: fly_n<1>'s loop (depth-rate flights, stages all
// cached) unrolled into single RK4 steps, so two can take turns.
struct StepCursor {
  const RunFlight::StagesView view;
  const model::PrescribedPitchDynamics& dynamics;
  const model::SkinFrictionFactor friction;
  std::vector<double>& z;
  std::size_t last;
  Impulse p;
  double depth = 0.0, h = 0.0;
  std::size_t i = 0, stage = 0, flown = 0;
  int s = 0, steps = 0;
  bool flying = true;
  FlightTrace* trace = nullptr;       // this flight's, written as it flies
  const FlightTrace* join = nullptr;  // another's, joined where the states meet
  bool joined = false;                // met it: the rest is join_rest()'s

  // At interval i's start: its sub-steps, or the interval's end where it has none.
  void open_interval() {
    while (flying) {
      if (i >= last) {
        flying = false;
        return;
      }
      const double dt = view.time_s[i + 1] - view.time_s[i];
      steps = view.pitch.steps(i);
      h = dt / steps;
      depth = z[i - view.first];
      s = 0;
      if (steps > 0) return;
      close_interval();
    }
  }
  void close_interval() {
    if (!p.allFinite() || !std::isfinite(depth)) {  // the rest of the run stays NaN: unflyable
      flying = false;
      return;
    }
    z[i + 1 - view.first] = depth;
    flown = i + 1;
    ++i;
    const std::size_t n = i - view.first;
    if (n % FlightTrace::kEvery != 0) return;
    const std::size_t m = n / FlightTrace::kEvery;
    if (trace != nullptr) trace->checkpoints[m].emplace(FlightTrace::Checkpoint{p, friction});
    if (join == nullptr || i >= last || !join->checkpoints[m].has_value()) return;
    const FlightTrace::Checkpoint& there = *join->checkpoints[m];
    if (std::memcmp(p.data(), there.p.data(), sizeof(double) * 2) == 0 &&
        std::memcmp(&friction, &there.friction, sizeof friction) == 0) {
      joined = true;
      flying = false;
    }
  }
  // Records a step's depth increment (dz) in the trace.
  void traced(double dz) const {
    if (trace != nullptr) trace->increments[stage / 3] = dz;
  }
  // The rest of a joined flight: the joined trace's increments onto this
  // flight's depth, interval by interval as open_interval and
  // close_interval add them (the impulses, the joined flight's, are finite
  // to its last: FlightTrace::last).
  void join_rest() {
    while (i < last) {
      const int n = view.pitch.steps(i);
      depth = z[i - view.first];
      for (int k = 0; k < n; ++k, stage += 3) {
        const double dz = join->increments[stage / 3];
        depth += dz;
        traced(dz);
      }
      if (!std::isfinite(depth)) return;
      z[i + 1 - view.first] = depth;
      flown = i + 1;
      ++i;
      const std::size_t m = (i - view.first) / FlightTrace::kEvery;
      if (trace != nullptr && (i - view.first) % FlightTrace::kEvery == 0) trace->checkpoints[m] = join->checkpoints[m];
    }
  }
};

}  // namespace

template <std::size_t N>
std::array<std::size_t, N> RunFlight::fly_runs(const std::array<RunQuestion, N>& q) {
  // Each flight after the first its own copy of the dynamics (its stage
  // cache), on the heap: on this frame, the frame's size moved with the
  // cursors' (FlightTrace's fields) and comet-2016 took 4 % more CPU for the
  // same instructions (callgrind), GliderDynamics::rigid_masses 4x its samples
  // (perf) - loads and stores of the copies meeting the stage's own frame in
  // the core's memory disambiguation, as far as measured.
  const auto heap_copies = std::make_unique<std::array<std::optional<model::PrescribedPitchDynamics>, N>>();
  std::array<std::optional<model::PrescribedPitchDynamics>, N>& copies = *heap_copies;
  std::array<std::optional<StepCursor>, N> cursors;
  for (std::size_t k = 0; k < N; ++k) {
    if (k > 0) copies[k].emplace(q[k].run->c_.dynamics);
    const model::PrescribedPitchDynamics& dynamics = k > 0 ? *copies[k] : q[k].run->c_.dynamics;
    const SpinUpEnd* from = q[k].from;
    const bool resume = from != nullptr && from->friction.has_value();
    cursors[k].emplace(StepCursor{q[k].run->view(), dynamics, resume ? *from->friction : dynamics.skin_friction(),
                                  *q[k].z, q[k].last,
                                  resume ? from->p : Impulse(dynamics.impulse(q[k].v1, q[k].v3, q[k].run->in0_))});
  }
  std::array<StepCursor*, N> f;
  for (std::size_t k = 0; k < N; ++k) {
    StepCursor& c = *cursors[k];
    f[k] = &c;
    c.z.assign(c.last - c.view.first + 1, kNaN);
    c.z[0] = 0.0;
    c.i = c.view.first;
    const SpinUpEnd* from = q[k].from;
    if (from != nullptr && from->friction.has_value()) {  // on from the spin-up's end
      const RunFlight& run = *q[k].run;
      std::copy(from->rel.begin(), from->rel.end(), c.z.begin());
      c.i = run.spin_up_last_;
      c.stage = run.spin_up_stage_;
    }
    c.flown = c.i;
    const RunFlight& run = *q[k].run;
    if (q[k].trace != nullptr) {
      c.trace = q[k].trace;
      c.trace->last = 0;  // complete once flown to `last`
      c.trace->joined_at = 0;
      c.trace->checkpoints.assign((c.last - c.view.first) / FlightTrace::kEvery + 1, std::nullopt);
      c.trace->increments.assign(run.stages_.stages.size() / 3, kNaN);
    }
    if (q[k].join != nullptr && q[k].join->last >= c.last) c.join = q[k].join;
    c.open_interval();
  }
  const Derivative kIdle{Impulse::Zero(), 0.0};
  while (std::any_of(f.begin(), f.end(), [](const StepCursor* c) { return c->flying; })) {
    // One RK4 step of each flight still flying, stage by stage across them.
    std::array<const model::PrescribedPitchInputs*, N> in{};
    std::array<Derivative, N> d1, d2, d3, d4;
    for (std::size_t k = 0; k < N; ++k) {
      const StepCursor& c = *f[k];
      in[k] = c.flying ? &c.view.stages[c.stage] : nullptr;
      d1[k] = c.flying ? c.dynamics.derivative(c.p, in[k][0], c.friction) : kIdle;
    }
    for (std::size_t k = 0; k < N; ++k) {
      const StepCursor& c = *f[k];
      d2[k] = c.flying ? c.dynamics.derivative(Impulse(c.p + 0.5 * c.h * d1[k].p_dot), in[k][1], c.friction) : kIdle;
    }
    for (std::size_t k = 0; k < N; ++k) {
      const StepCursor& c = *f[k];
      d3[k] = c.flying ? c.dynamics.derivative(Impulse(c.p + 0.5 * c.h * d2[k].p_dot), in[k][1], c.friction) : kIdle;
    }
    for (std::size_t k = 0; k < N; ++k) {
      const StepCursor& c = *f[k];
      d4[k] = c.flying ? c.dynamics.derivative(Impulse(c.p + c.h * d3[k].p_dot), in[k][2], c.friction) : kIdle;
    }
    for (std::size_t k = 0; k < N; ++k) {
      StepCursor& c = *f[k];
      if (!c.flying) continue;
      const double h = c.h;
      const double dz =
          h / 6.0 *
          (d1[k].depth_rate_m_s + 2.0 * d2[k].depth_rate_m_s + 2.0 * d3[k].depth_rate_m_s + d4[k].depth_rate_m_s);
      c.depth += dz;
      c.traced(dz);
      c.p += h / 6.0 * (d1[k].p_dot + 2.0 * d2[k].p_dot + 2.0 * d3[k].p_dot + d4[k].p_dot);
      c.stage += 3;
      if (++c.s < c.steps) continue;
      c.close_interval();
      c.open_interval();
    }
  }
  std::array<std::size_t, N> flown;
  for (std::size_t k = 0; k < N; ++k) {
    StepCursor& c = *f[k];
    if (c.joined) {
      if (c.trace != nullptr) c.trace->joined_at = c.i;
      c.join_rest();
    }
    if (c.trace != nullptr && c.flown == c.last) c.trace->last = c.last;
    flown[k] = c.flown;
  }
  return flown;
}

template std::array<std::size_t, 1> RunFlight::fly_runs<1>(const std::array<RunQuestion, 1>&);
template std::array<std::size_t, 2> RunFlight::fly_runs<2>(const std::array<RunQuestion, 2>&);
template std::array<std::size_t, 3> RunFlight::fly_runs<3>(const std::array<RunQuestion, 3>&);

void RunFlight::cache_stages(std::size_t last) const {
  refresh_pumped(last);
  // The pumped volume lagged from the last cached stage's, as fly_n carries it.
  double lagged = stages_.stages.empty() ? in0_.pumped_volume_m3 : stages_.stages.back().pumped_volume_m3;
  for (std::size_t i = first_ + stages_.intervals; i < last; ++i) {
    const int steps = c_.pitch.steps(i);
    for (int s = 0; s < steps; ++s) {
      const model::PrescribedPitchInputs a = inputs(i, 2 * s, steps, lagged, 2 * s);
      const model::PrescribedPitchInputs b = inputs(i, 2 * s + 1, steps, lagged, 2 * s);
      const model::PrescribedPitchInputs c = inputs(i, 2 * s + 2, steps, lagged, 2 * s);
      stages_.stages.insert(stages_.stages.end(), {a, b, c});
      lagged = c.pumped_volume_m3;
    }
    stages_.pumped = ++stages_.intervals;
  }
}

void RunFlight::ground_depth(std::size_t flown, const std::vector<double>& rel, std::vector<double>& z) const {
  integrate_water(flown);
  z.assign(rel.size(), kNaN);
  z[0] = t_.depth_m[first_] + rel[0];
  for (std::size_t i = first_; i < flown; ++i)
    z[i + 1 - first_] = t_.depth_m[first_] + rel[i + 1 - first_] + stages_.water[i - first_];
}

void RunFlight::integrate_water(std::size_t flown) const {
  const Track& t = t_;
  if (stages_.water.size() >= flown - first_) return;
  double water = stages_.water.empty() ? 0.0 : stages_.water.back();
  const bool bins_kept = c_.has_profile() && this->bins_kept();
  for (std::size_t i = first_ + stages_.water.size(); i < flown; ++i) {
    const double dt = t.time_s[i + 1] - t.time_s[i];
    const int steps = c_.pitch.steps(i);
    const double h = dt / steps;
    if (!c_.has_profile()) {
      // The same sum with the one velocity at every stage (no depths to look up).
      const double w = c_.water_w(0.0);
      for (int s = 0; s < steps; ++s) water += h / 6.0 * (w + 2.0 * w + 2.0 * w + w);
    }
    const std::uint32_t* bins = bins_kept ? stage_bins(i, steps) : nullptr;
    for (int s = 0; s < steps && bins != nullptr; ++s) {
      // VerticalVelocityProfile::at at the stages' depths, their bins looked up once per geometry.
      const std::vector<double>& w = c_.profile()->w_m_s;
      const double wa = w[bins[3 * s]], wb = w[bins[3 * s + 1]], wc = w[bins[3 * s + 2]];
      water += h / 6.0 * (wa + 2.0 * wb + 2.0 * wb + wc);
    }
    for (int s = 0; s < steps && c_.has_profile() && bins == nullptr; ++s) {
      const double wa = c_.water_w(lerp(t.depth_m[i], t.depth_m[i + 1], static_cast<double>(s) / steps));
      const double wb = c_.water_w(lerp(t.depth_m[i], t.depth_m[i + 1], (s + 0.5) / steps));
      const double wc = c_.water_w(lerp(t.depth_m[i], t.depth_m[i + 1], static_cast<double>(s + 1) / steps));
      water += h / 6.0 * (wa + 2.0 * wb + 2.0 * wb + wc);
    }
    stages_.water.push_back(water);
  }
}

RunFlight::SpinUpWater RunFlight::spin_up_water() const {
  integrate_water(spin_up_last_);
  return {std::span<const double>(stages_.water).first(spin_up_last_ - first_), c_.water_w(in0_.depth_m)};
}

bool RunFlight::bins_kept() const {
  const VerticalVelocityProfile& profile = *c_.profile();
  if (profile.w_m_s.empty()) return false;  // no bins: at() is 0
  auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  if (!same(stages_.bins_first_m, profile.first_m) || !same(stages_.bins_bin_m, profile.bin_m) ||
      stages_.bins_count != profile.w_m_s.size()) {
    stages_.bins_first_m = profile.first_m;
    stages_.bins_bin_m = profile.bin_m;
    stages_.bins_count = profile.w_m_s.size();
    stages_.bins_offset.clear();
    stages_.bins.clear();
  }
  return true;
}

const std::uint32_t* RunFlight::stage_bins(std::size_t i, int steps) const {
  const VerticalVelocityProfile& profile = *c_.profile();
  const std::size_t interval = i - first_;
  if (interval < stages_.bins_offset.size()) return &stages_.bins[stages_.bins_offset[interval]];
  if (interval > stages_.bins_offset.size()) return nullptr;  // filled in order only: looked up directly
  const Track& t = t_;
  stages_.bins_offset.push_back(stages_.bins.size());
  for (int s = 0; s < steps; ++s) {
    for (const double f : {static_cast<double>(s) / steps, (s + 0.5) / steps, static_cast<double>(s + 1) / steps})
      stages_.bins.push_back(static_cast<std::uint32_t>(profile.bin(lerp(t.depth_m[i], t.depth_m[i + 1], f))));
  }
  return &stages_.bins[stages_.bins_offset[interval]];
}

void RunFlight::guess_start(double& v1, double& v3) const {
  const model::PrescribedPitchDynamics& dynamics = c_.dynamics;
  const auto steady = model::steady_glide_for_pitch(c_.vehicle.hydro, in0_.density_kg_m3, in0_.theta_rad,
                                                    dynamics.net_buoyancy_kg(in0_));
  if (!steady.glide) return;
  v1 = steady.glide->speed_m_s * std::cos(steady.glide->alpha_rad);
  v3 = steady.glide->speed_m_s * std::sin(steady.glide->alpha_rad);
  const double steady_rate = dynamics.depth_rate_m_s(dynamics.impulse(v1, v3, in0_), in0_);
  const double measured_rate = t_.depth_rate_m_s[first_] - c_.water_w(in0_.depth_m);
  if (std::abs(steady_rate) > 1e-3 && std::isfinite(measured_rate)) {
    const double scale = std::clamp(measured_rate / steady_rate, 0.0, 1.5);
    v1 *= scale;
    v3 *= scale;
  }
}

void RunFlight::fit_start(double& v1, double& v3, std::vector<double>& zf, std::vector<double>& rel,
                          SpinUpEnd& end) const {
  end.friction.reset();
  guess_start(v1, v3);
  const Track& t = t_;
  const std::size_t fit_last = spin_up_last_;
  if (fit_last < first_ + 3) return;
  const std::size_t n = fit_last - first_;
  // The residual of a flight that reached fit_last. Not through the depth
  // lag: the start state is a nuisance fitted on a part never scored, and
  // without the lag it stays the same for every lag, so a depth_lag fit
  // reuses the flight (only the depth over ground is read late again).
  auto residual = [&](std::size_t reached, const std::vector<double>& flight, Eigen::VectorXd& out) {
    if (reached != fit_last) return false;
    ground_depth(fit_last, flight, zf);
    out.resize(static_cast<Eigen::Index>(n));
    for (std::size_t k = 1; k <= n; ++k) out[static_cast<Eigen::Index>(k - 1)] = zf[k] - t.depth_m[first_ + k];
    return true;
  };
  // Chord method: the depth over half a minute is nearly linear in the
  // start velocities, so the Jacobian at the guess serves every step
  // (each step then costs one flight of the spin-up, not three).
  Eigen::VectorXd r, r_trial, r_a, r_b;
  constexpr double kDelta = 1e-4;  // m/s, finite-difference step
  // The guess and its two finite differences, flown side by side (the same
  // bits as one after the other).
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> rel_a, rel_b, rel_c;
  std::vector<double>* const trial_flights_all[] = {&rel, &rel_a, &rel_b, &rel_c};
  std::array<std::vector<double>*, kTrialsTogether> trial_flights;
  std::copy_n(std::begin(trial_flights_all), kTrialsTogether, trial_flights.begin());
  std::array<SpinUpEnd, 3> guess_ends;
  const std::array<std::size_t, 3> flown = fly_n<3>({v1, v1 + kDelta, v1}, {v3, v3, v3 + kDelta}, fit_last,
                                                    {&rel, &rel_a, &rel_b}, nullptr, {kInf, kInf, kInf}, &guess_ends);
  // Where the flight from the start state stands at the spin-up's end: the guess's, then each step taken.
  auto stood = [&](const SpinUpEnd& e, const std::vector<double>& flight) {
    end.p = e.p;
    end.friction = e.friction;
    end.rel.assign(flight.begin(), flight.end());
  };
  stood(guess_ends[0], rel);
  if (!(residual(flown[0], rel, r) && residual(flown[1], rel_a, r_a) && residual(flown[2], rel_b, r_b))) return;
  Eigen::MatrixXd jac(r.size(), 2);
  jac.col(0) = (r_a - r) / kDelta;
  jac.col(1) = (r_b - r) / kDelta;
  const Eigen::Matrix2d normal = jac.transpose() * jac + 1e-9 * Eigen::Matrix2d::Identity();
  const auto solver = normal.ldlt();
  for (int iteration = 0; iteration < 8; ++iteration) {
    Eigen::Vector2d step = solver.solve(-jac.transpose() * r);
    if (!step.allFinite()) break;
    double taken = 0.0;  // length of the step taken (halved until the misfit does not grow)
    // A trial is taken where its squared norm is <= the current one's. A
    // running sum over its first samples that already exceeds that by more
    // than 2 n eps relative decides "not taken" early, and the same as the
    // whole norm would: a float sum of n non-negative terms, in any order,
    // is within (n - 1) u of the exact sum (u = eps / 2), so the two
    // summations differ by less than 2 n eps, and the samples left only add.
    // (The trials not taken then fly about half the spin-up, comet-2016.)
    const double stop_above =
        r.squaredNorm() * (1.0 + 2.0 * static_cast<double>(n) * std::numeric_limits<double>::epsilon());
    // The halvings' trials (the step, a half, a quarter, an eighth) flown
    // kTrialsTogether side by side (each the same bits as alone): the first
    // taken is taken, as when they were flown one after the other, and the
    // ones after it beside it cost little (the core was idle).
    for (std::size_t round = 0; round < kHalvings / kTrialsTogether && taken == 0.0; ++round) {
      std::array<double, kTrialsTogether> a{}, b{};
      std::array<Eigen::Vector2d, kTrialsTogether> steps;
      for (std::size_t k = 0; k < kTrialsTogether; ++k) {
        a[k] = std::clamp(v1 + step[0], -1.5, 1.5);
        b[k] = std::clamp(v3 + step[1], -1.5, 1.5);
        steps[k] = step;
        step *= 0.5;
      }
      std::array<double, kTrialsTogether> bound;
      bound.fill(stop_above);
      std::array<SpinUpEnd, kTrialsTogether> trial_ends;
      const auto reached = fly_n<kTrialsTogether>(a, b, fit_last, trial_flights, nullptr, bound, &trial_ends);
      for (std::size_t k = 0; k < kTrialsTogether; ++k) {
        if (residual(reached[k], *trial_flights[k], r_trial) && r_trial.squaredNorm() <= r.squaredNorm()) {
          stood(trial_ends[k], *trial_flights[k]);
          v1 = a[k];
          v3 = b[k];
          r.swap(r_trial);
          taken = steps[k].norm() + 1e-300;
          break;
        }
      }
    }
    if (taken < 1e-6) break;  // converged, or no step helps
  }
}

}  // namespace glider::diagnose::detail
