// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/dynamic_flight_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "glider/diagnose/depth_lag.hpp"
#include "run_flight.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Main flights of this many runs flown side by side (RunFlight::fly_runs).
constexpr std::size_t kRunsTogether = 3;

// FNV-1a over a key's bytes: a memo's bucket; its entries are then compared bit for bit.
class BitsHash {
 public:
  template <typename T>
  BitsHash& add(std::span<const T> values) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
    for (std::size_t k = 0; k < values.size_bytes(); ++k) hash_ = (hash_ ^ bytes[k]) * 1099511628211ULL;
    return *this;
  }
  template <typename T>
  BitsHash& add(const T& value) {
    return add(std::span<const T>(&value, 1));
  }
  BitsHash& add(const VerticalVelocityProfile* profile) {
    add(profile != nullptr);
    if (profile == nullptr) return *this;
    return add(profile->bin_m).add(profile->first_m).add(std::span<const double>(profile->w_m_s));
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ULL;
};

// Bit for bit (-0.0 is not +0.0 here): the same question, so the same answer.
bool same_bits(std::span<const double> a, std::span<const double> b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
}

bool same_profile(bool has_profile, const VerticalVelocityProfile& kept, const VerticalVelocityProfile* profile) {
  if (has_profile != (profile != nullptr)) return false;
  return profile == nullptr || (same_bits(std::span(&kept.bin_m, 1), std::span(&profile->bin_m, 1)) &&
                                same_bits(std::span(&kept.first_m, 1), std::span(&profile->first_m, 1)) &&
                                same_bits(kept.w_m_s, profile->w_m_s));
}

}  // namespace

DynamicFlightModel::DynamicFlightModel(const model::VehicleParams& nominal, const Track& track, double max_step_s,
                                       std::size_t traced_samples)
    : nominal_(nominal),
      track_(track),
      max_step_s_(max_step_s),
      stage_pitch_(std::make_unique<detail::StagePitchTable>(track, max_step_s)),
      relative_flights_(track.run_first.size()),
      start_states_(track.run_first.size()),
      run_stages_(track.run_first.size()),
      traced_samples_(traced_samples) {}

DynamicFlightModel::~DynamicFlightModel() = default;

void DynamicFlightModel::predict(const EffectValues& x, DepthLagForm depth_lag_form, bool use_ctd,
                                 std::span<const std::size_t> samples, std::vector<double>& out,
                                 const VerticalVelocityProfile* profile) const {
  fly(x, depth_lag_form, use_ctd, samples, &out, nullptr, profile);
}

void DynamicFlightModel::predict(const EffectValues& x, bool use_ctd, std::span<const std::size_t> samples,
                                 std::vector<double>& out, const VerticalVelocityProfile* profile) const {
  fly(x, DepthLagForm::kDelay, use_ctd, samples, &out, nullptr, profile);
}

// The speed through the water is the flight's: no depth is read, in either form.
void DynamicFlightModel::predict_speed(const EffectValues& x, bool use_ctd, std::span<const std::size_t> samples,
                                       std::vector<double>& out) const {
  fly(x, DepthLagForm::kDelay, use_ctd, samples, nullptr, &out, nullptr);
}

void DynamicFlightModel::fly(const EffectValues& x, DepthLagForm depth_lag_form, bool use_ctd,
                             std::span<const std::size_t> samples, std::vector<double>* depth_rate,
                             std::vector<double>* speed, const VerticalVelocityProfile* profile) const {
  const bool memo = samples.size() <= kFlightMemoSamples;
  const std::uint64_t hash = memo ? BitsHash()
                                        .add(std::span<const double>(x))
                                        .add(depth_lag_form)
                                        .add(use_ctd)
                                        .add(depth_rate != nullptr)
                                        .add(speed != nullptr)
                                        .add(profile)
                                        .add(samples)
                                        .value()
                                  : 0;
  auto same_question = [&](const FlightAnswer& a) {
    return same_bits(a.values, x) && a.depth_lag_form == depth_lag_form && a.use_ctd == use_ctd &&
           a.depth_rate == (depth_rate != nullptr) && a.speed == (speed != nullptr) &&
           same_profile(a.has_profile, a.profile, profile) &&
           std::equal(a.samples.begin(), a.samples.end(), samples.begin(), samples.end());
  };
  if (memo) {
    for (auto [it, end] = answers_.equal_range(hash); it != end; ++it) {
      const FlightAnswer& a = it->second;
      if (!same_question(a)) continue;
      if (depth_rate != nullptr) *depth_rate = a.depth_rate_out;
      if (speed != nullptr) *speed = a.speed_out;
      return;
    }
  }
  fly_uncached(x, depth_lag_form, use_ctd, samples, depth_rate, speed, profile);
  const std::size_t bytes =
      sizeof(FlightAnswer) + samples.size_bytes() +
      sizeof(double) * ((depth_rate != nullptr ? samples.size() : 0) + (speed != nullptr ? samples.size() : 0) +
                        (profile != nullptr ? profile->w_m_s.size() : 0));
  if (!memo || answer_bytes_ + bytes > kFlightMemoBytes) return;
  answer_bytes_ += bytes;
  FlightAnswer& a = answers_.emplace(hash, FlightAnswer{})->second;
  a.values = x;
  a.depth_lag_form = depth_lag_form;
  a.use_ctd = use_ctd;
  a.depth_rate = depth_rate != nullptr;
  a.speed = speed != nullptr;
  a.has_profile = profile != nullptr;
  if (profile != nullptr) a.profile = *profile;
  a.samples.assign(samples.begin(), samples.end());
  if (depth_rate != nullptr) a.depth_rate_out = *depth_rate;
  if (speed != nullptr) a.speed_out = *speed;
}

// Fly up to the last requested sample of a run and on through its
// estimator window (the slope at a sample uses the samples after it), on to
// the next stored depth (a decimated log's rows between are read as the line
// to it), and at least one sample further: a centred difference (no window, or none
// after the sample within it) needs the next sample. A prediction then
// never depends on which other samples are asked for.
std::size_t DynamicFlightModel::last_needed(std::size_t end, std::size_t last_requested) const {
  const Track& t = track_;
  std::size_t last = std::min(end - 1, last_requested);
  const double window_end_s = t.time_s[last] + t.rate_half_window_s;
  if (last + 1 < end) ++last;
  while (last + 1 < end && t.time_s[last + 1] <= window_end_s) ++last;
  // The depth there may be the line to the next stored depth (read_as_stored).
  while (last + 1 < end && !t.depth_stored[last]) ++last;
  return last;
}

// The start. A run begins where the glider leaves the surface or a gap,
// far from a steady glide: leaving the surface it sinks at a large angle
// of attack and takes a minute or two to reach its glide (surge is
// slow). Started on the steady glide, the model dives too fast for that
// long, in the warm top layer, and a fit reads it as buoyancy that
// follows temperature (+5.5e-6 /K of thermal expansion on clean SIL
// data). So the two body velocities at the start are nuisance
// parameters, fitted (Gauss-Newton) to the measured depth over the
// spin-up, which is never scored. The start state depends on the values
// (the depth lag and the water's velocity aside), the density source and
// the water the spin-up meets only (RunFlight::spin_up_water): they are
// remembered (kStartStateBytes; about a third of the start fits of a real
// log's diagnosis repeat one: the Jacobian's depth-lag column and a
// profile's bins below the spin-up, a refit), the same bits.
const detail::SpinUpEnd* DynamicFlightModel::start_state(const detail::RunFlight& run_flight, std::size_t run,
                                                         const EffectValues& x, bool use_ctd, double& v1, double& v3,
                                                         detail::SpinUpEnd& own) const {
  EffectValues start_key = x;
  start_key[static_cast<std::size_t>(Effect::kDepthLag)] = 0.0;
  start_key[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)] = 0.0;
  const detail::RunFlight::SpinUpWater water = run_flight.spin_up_water();
  const std::uint64_t hash = BitsHash()
                                 .add(std::span<const double>(start_key))
                                 .add(use_ctd)
                                 .add(water.start_w)
                                 .add(water.displacement)
                                 .value();
  std::unordered_multimap<std::uint64_t, StartState>& starts = start_states_[run];
  for (auto [it, end] = starts.equal_range(hash); it != end; ++it) {
    const StartState& s = it->second;
    if (same_bits(s.values, start_key) && s.use_ctd == use_ctd &&
        same_bits(std::span(&s.start_w, 1), std::span(&water.start_w, 1)) && same_bits(s.water, water.displacement)) {
      v1 = s.v1;
      v3 = s.v3;
      return s.end.get();
    }
  }
  v1 = 0.0;
  v3 = 0.0;
  run_flight.fit_start(v1, v3, fit_buffer_, fit_relative_buffer_, own);
  const std::size_t bytes = sizeof(StartState) + water.displacement.size_bytes() + own.rel.size() * sizeof(double);
  if (start_state_bytes_ + bytes > kStartStateBytes) return &own;
  start_state_bytes_ += bytes;
  StartState& kept =
      starts
          .emplace(hash, StartState{start_key, use_ctd, water.start_w,
                                    std::vector<double>(water.displacement.begin(), water.displacement.end()), v1, v3,
                                    std::make_unique<detail::SpinUpEnd>(std::move(own))})
          ->second;
  return kept.end.get();
}

// The run's flight through the water, reused when only the water's
// velocity changed and the start state came out the same (a profile bin
// the run's spin-up does not reach: the Jacobian of a depth profile costs
// a flight per bin otherwise). Null where it is not remembered.
const DynamicFlightModel::RelativeFlight* DynamicFlightModel::kept_flight(std::size_t run, const EffectValues& key,
                                                                          bool use_ctd, double v1, double v3,
                                                                          std::size_t last, bool with_speed) const {
  for (const RelativeFlight& flight : relative_flights_[run].flights) {
    if (flight.valid && flight.key == key && flight.use_ctd == use_ctd && flight.v1 == v1 && flight.v3 == v3 &&
        flight.last >= last && (!with_speed || flight.has_speed))
      return &flight;
  }
  return nullptr;
}

// The slot a new flight of the run replaces (round robin), its buffers kept for reuse.
DynamicFlightModel::RelativeFlight& DynamicFlightModel::flight_slot(std::size_t run) const {
  RunRelativeFlights& kept = relative_flights_[run];
  if (kept.flights.size() < kRelativeFlights) kept.flights.emplace_back();
  RelativeFlight& flight = kept.flights[kept.next];
  kept.next = (kept.next + 1) % kRelativeFlights;
  return flight;
}

// A kept main flight's trace that a new flight of the run under `key` and
// the density source may join (FlightTrace): the same key bit for bit (the
// same vehicle and stage inputs), traced to the run's end, not in `slot`
// (the one the new flight is about to overwrite). Null where none is.
const detail::FlightTrace* DynamicFlightModel::joinable_trace(std::size_t run, const EffectValues& key, bool use_ctd,
                                                              const RelativeFlight& slot) const {
  for (const RelativeFlight& flight : relative_flights_[run].flights) {
    if (&flight == &slot || !flight.valid || flight.use_ctd != use_ctd || flight.trace == nullptr ||
        flight.trace->last == 0 || !same_bits(flight.key, key))
      continue;
    return flight.trace.get();
  }
  return nullptr;
}

// The key a run's flight through the water depends on: the values but the
// water's velocity and the depth lag (the sensor's, not the flight's).
EffectValues DynamicFlightModel::flight_key(const EffectValues& x) {
  EffectValues key = x;
  key[static_cast<std::size_t>(Effect::kVerticalWaterVelocity)] = 0.0;
  key[static_cast<std::size_t>(Effect::kDepthLag)] = 0.0;
  return key;
}

// The run's depth over ground, read late by the depth lag in its form as
// the sensor read it, through the very estimator the measurement went through (the
// track's windowed slope): like is compared with like, also in turns,
// where a +-5 s slope is not the instantaneous rate. Fills the requested
// samples of this run from `next` on; returns the next one after them.
std::size_t DynamicFlightModel::read_run(const detail::RunFlight& run_flight, const RelativeFlight& flight,
                                         std::size_t last, DepthLagForm depth_lag_form, double depth_lag_s,
                                         std::span<const std::size_t> samples, std::size_t next,
                                         std::vector<double>* depth_rate, std::vector<double>* speed) const {
  const Track& t = track_;
  const std::size_t first = run_flight.first(), end = run_flight.end();
  const std::size_t flown = std::min(flight.flown, last);
  const std::vector<double>& u = flight.speed;
  std::vector<double>& z = depth_buffer_;
  run_flight.ground_depth(flown, flight.depth, z);
  const std::size_t count = flown - first + 1;
  const std::span<const double> time = std::span(t.time_s).subspan(first, count);
  read_depth_late(depth_lag_form, time, std::span(z).first(count), depth_lag_s);  // as the sensor read it
  // ... and as the log stored it: between the depths a decimated log kept,
  // the reader's straight line, as the measured depth between them.
  read_as_stored(time, std::span(t.depth_stored).subspan(first, count), std::span(z).first(count), t.max_gap_s);
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
  return next;
}

// Each run that holds a requested sample is flown from its fitted start
// state (detail::RunFlight: RK4 at <= max_step_s through the log's inputs)
// and read where asked. The runs' start states first, then the flights not
// remembered, kRunsTogether runs side by side (their stages cached first)
// (RunFlight::fly_runs: the same bits as one after the other), then the
// reading, run by run.
void DynamicFlightModel::fly_uncached(const EffectValues& x, DepthLagForm depth_lag_form, bool use_ctd,
                                      std::span<const std::size_t> samples, std::vector<double>* depth_rate,
                                      std::vector<double>* speed, const VerticalVelocityProfile* profile) const {
  if (depth_rate != nullptr) depth_rate->assign(samples.size(), kNaN);
  if (speed != nullptr) speed->assign(samples.size(), kNaN);
  if (!flyable(x)) return;  // no negative drag or lift
  const detail::FlightConditions conditions(nominal_, x, use_ctd, track_, profile, max_step_s_, *stage_pitch_);
  const double depth_lag_s = std::abs(x[static_cast<std::size_t>(Effect::kDepthLag)]);  // no sign, as the pump's
  const Track& t = track_;
  const EffectValues key = flight_key(x);
  const bool with_speed = speed != nullptr;
  // A flight is flown to its run's end (fly_to), though read only up to
  // `last`: a flight's samples do not depend on how far it goes, and a fit's
  // closing question (its solution, asked at the training and held-out
  // samples together) then finds the flight its last trial flew (asked at the
  // training samples, which end a little earlier) instead of flying it again.
  struct AskedRun {
    detail::RunFlight run_flight;
    std::size_t run, last, fly_to;
    double v1, v3;
    const RelativeFlight* flight;  // null: to fly
    detail::SpinUpEnd own;         // the spin-up's end where the start states do not keep it
    const detail::SpinUpEnd* spin_up;
  };
  std::vector<AskedRun> asked;
  asked.reserve(t.run_first.size());
  std::size_t next = 0;  // next requested sample
  for (std::size_t run = 0; run < t.run_first.size() && next < samples.size(); ++run) {
    const std::size_t end = t.run_end(run);
    if (samples[next] >= end) continue;  // nothing requested in this run (every sample is in a run)
    while (next < samples.size() && samples[next] < end) ++next;
    AskedRun& a = asked.emplace_back(AskedRun{detail::RunFlight(conditions, t.run_first[run], end, run_stages_[run]),
                                              run,
                                              0,
                                              end - 1,
                                              0.0,
                                              0.0,
                                              nullptr,
                                              {},
                                              nullptr});
    a.spin_up = start_state(a.run_flight, run, x, use_ctd, a.v1, a.v3, a.own);
    a.last = last_needed(end, samples.back());
    a.flight = kept_flight(run, key, use_ctd, a.v1, a.v3, a.last, with_speed);
  }
  auto keep = [&](AskedRun& a, RelativeFlight& slot, std::size_t flown) {
    slot = {true,
            key,
            use_ctd,
            a.v1,
            a.v3,
            a.fly_to,
            flown,
            with_speed,
            std::move(slot.depth),
            std::move(slot.speed),
            std::move(slot.trace)};
    a.flight = &slot;
  };
  std::vector<AskedRun*> ready;  // to fly side by side (their stages cached)
  for (AskedRun& a : asked) {
    if (a.flight != nullptr) continue;
    if (with_speed) {
      RelativeFlight& slot = flight_slot(a.run);
      if (slot.trace != nullptr) slot.trace->last = 0;  // fly() keeps none: the slot's old one is not this flight's
      keep(a, slot, a.run_flight.fly(a.v1, a.v3, a.fly_to, slot.depth, &slot.speed));
    } else {
      a.run_flight.cache_stages(a.fly_to);  // the run's first flight under these inputs: its stages now
      ready.push_back(&a);
    }
  }
  auto fly_together = [&]<std::size_t N>(std::span<AskedRun* const, N> group) {
    std::array<RelativeFlight*, N> slots;
    std::array<detail::RunFlight::RunQuestion, N> q;
    for (std::size_t k = 0; k < N; ++k) {
      AskedRun& a = *group[k];
      slots[k] = &flight_slot(a.run);
      q[k] = {&a.run_flight, a.v1, a.v3, a.fly_to, &slots[k]->depth, a.spin_up};
      if (slots[k]->trace != nullptr) slots[k]->trace->last = 0;  // the slot's old flight's
      if (a.fly_to - a.run_flight.first() >= traced_samples_) {
        if (slots[k]->trace == nullptr) slots[k]->trace = std::make_unique<detail::FlightTrace>();
        q[k].trace = slots[k]->trace.get();
        q[k].join = joinable_trace(a.run, key, use_ctd, *slots[k]);
      }
    }
    const std::array<std::size_t, N> flown = detail::RunFlight::fly_runs<N>(q);
    for (std::size_t k = 0; k < N; ++k) {
      keep(*group[k], *slots[k], flown[k]);
      if (q[k].trace != nullptr && q[k].trace->joined_at != 0) ++joined_flights_;
    }
  };
  std::span<AskedRun* const> left(ready);
  for (; left.size() >= kRunsTogether; left = left.subspan(kRunsTogether)) fly_together(left.first<kRunsTogether>());
  if (left.size() == 2) fly_together(left.first<2>());
  if (left.size() == 1) fly_together(left.first<1>());
  next = 0;
  for (const AskedRun& a : asked)
    next = read_run(a.run_flight, *a.flight, a.last, depth_lag_form, depth_lag_s, samples, next, depth_rate, speed);
}

double DynamicFlightModel::ctd_density_anomaly() const {
  return deepest_density_anomaly(track_.depth_m, track_.density_kg_m3, nominal_.trim_density_kg_m3);
}

namespace {

EffectValues with_lag_magnitude(const EffectValues& values) {
  EffectValues x = values;
  double& lag = x[static_cast<std::size_t>(Effect::kDepthLag)];
  lag = std::abs(lag);
  return x;
}

}  // namespace

void DepthLagView::predict(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                           std::vector<double>& out, const VerticalVelocityProfile* profile) const {
  model_.predict(with_lag_magnitude(values), form_, use_ctd_density, samples, out, profile);
}

void DepthLagView::predict_speed(const EffectValues& values, bool use_ctd_density, std::span<const std::size_t> samples,
                                 std::vector<double>& out) const {
  model_.predict_speed(with_lag_magnitude(values), use_ctd_density, samples, out);
}

}  // namespace glider::diagnose
