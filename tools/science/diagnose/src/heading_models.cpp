// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_models.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "glider/diagnose/track.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// std::remainder is exact but slow (it was 40 % of a heading diagnosis, in
// the autopilot replay); inside [-pi, pi] it returns its argument (a half
// quotient rounds to the even 0), so that case skips it: same bits.
double wrap_pi(double a) {
  if (a >= -std::numbers::pi && a <= std::numbers::pi) return a;
  return std::remainder(a, 2.0 * std::numbers::pi);
}

// Rows are under water (the fin and the autopilot act) below this depth.
constexpr double kSubmergedM = 1.0;
// Integration step of the servo and yaw replays (s), at most.
constexpr double kStepS = 0.25;

// Index of the last row at or before t (rows sorted); SIZE_MAX before the first.
std::size_t row_at_or_before(std::span<const double> time, double t) {
  const auto it = std::upper_bound(time.begin(), time.end(), t);
  return it == time.begin() ? SIZE_MAX : static_cast<std::size_t>(it - time.begin()) - 1;
}

double value(const HeadingValues& v, HeadingEffect e) { return at(v, e); }

// The fin between two readings as the servo moves it: a command goes out at
// each reading and reaches the servo its dead time later, so the fin leaves
// this reading when the first command does that arrives before the next one
// (at this reading itself where the servo has no dead time), or earlier
// where only that reaches the next reading at the servo's speed; it moves at
// that speed and then holds (a straight line between readings 4 s apart
// would lag a fin move by ~1.5 s and blur it, which a fit reads as less fin
// authority; a fin leaving at the reading behind a dead time of 10.6 s on a
// 6.8 s cycle left 3.8 s early, which the fit read as a yaw delay of 4.1 s:
// docs/science.md "The fin between readings behind the servo's dead time").
double fin_between_rows(std::span<const double> time, std::span<const double> fin, double t, double rate,
                        double dead_time) {
  const std::size_t j = row_at_or_before(time, t);
  if (j == SIZE_MAX) return kNaN;
  if (j + 1 >= time.size() || !std::isfinite(fin[j + 1])) return fin[j];
  const double step = fin[j + 1] - fin[j];
  double leaves = time[j];
  if (dead_time > 0.0) {
    const auto sent = std::lower_bound(time.begin(), time.end(), time[j] - dead_time);
    const double arrives = *sent + dead_time;
    if (arrives < time[j + 1]) leaves = std::max(time[j], std::min(arrives, time[j + 1] - std::abs(step) / rate));
  }
  const double moved = rate * std::max(0.0, t - leaves);
  return fin[j] + std::clamp(step, -moved, moved);
}

void pick(const std::vector<double>& series, std::span<const std::size_t> at_index, std::vector<double>& out) {
  out.resize(at_index.size());
  for (std::size_t k = 0; k < at_index.size(); ++k) out[k] = series[at_index[k]];
}

}  // namespace

HeadingValues nominal_heading_values(const model::VehicleParams& vehicle, const AutopilotSettings& autopilot) {
  HeadingValues v{};
  at(v, HeadingEffect::kFinDelay) = vehicle.heading.fin_delay_s;
  at(v, HeadingEffect::kFinDeadband) = vehicle.heading.fin_deadband_rad;
  at(v, HeadingEffect::kYawDelay) = 0.0;
  at(v, HeadingEffect::kFinEffectiveness) = 1.0;
  at(v, HeadingEffect::kRollOffset) = 0.0;
  at(v, HeadingEffect::kYawTimeConstant) = vehicle.heading.yaw_time_constant_s;
  at(v, HeadingEffect::kAutopilotGain) = autopilot.gain;
  at(v, HeadingEffect::kAutopilotIntegral) = autopilot.igain;
  at(v, HeadingEffect::kAutopilotDgain) = autopilot.dgain;
  at(v, HeadingEffect::kAutopilotDelay) = 0.0;
  at(v, HeadingEffect::kAutopilotDeadband) = autopilot.heading_deadband_rad;
  at(v, HeadingEffect::kLiftFactor) = 1.0;
  return v;
}

std::vector<std::size_t> servo_rows(const HeadingTrack& t) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 1; i < t.row_time_s.size(); ++i) {
    if (std::isfinite(t.row_fin_rad[i]) && std::isfinite(t.row_fin_command_rad[i - 1]) &&
        t.row_depth_m[i] >= kSubmergedM && t.row_yo[i] >= 0 && t.row_time_s[i] - t.row_time_s[i - 1] <= t.max_gap_s) {
      rows.push_back(i);
    }
  }
  return rows;
}

std::vector<std::size_t> autopilot_rows(const HeadingTrack& t) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 1; i < t.row_time_s.size(); ++i) {
    const bool active = std::isfinite(t.row_command_rad[i]) && t.row_gliding[i];
    const bool was_active = std::isfinite(t.row_command_rad[i - 1]) && t.row_gliding[i - 1];
    if (active && was_active && std::isfinite(t.row_fin_command_rad[i]) && std::isfinite(t.row_heading_rad[i]) &&
        t.row_yo[i] >= 0) {
      rows.push_back(i);
    }
  }
  return rows;
}

// The servo: from each row the fin moves at the vehicle's speed toward the
// last command issued a dead time ago (a row's own command acts after its
// own measurement: c_fin is computed at the end of the cycle that read m_fin),
// unless that command is within the deadband of where the fin is then (the
// SIL's servo, model/simulator.cpp).
void predict_servo_fin(const HeadingTrack& t, std::span<const double> unlogged, const model::VehicleParams& vehicle,
                       const HeadingValues& values, std::span<const std::size_t> rows, std::vector<double>& out) {
  const double delay = std::abs(value(values, HeadingEffect::kFinDelay));
  const double deadband = std::abs(value(values, HeadingEffect::kFinDeadband));
  const double rate = vehicle.heading.fin_rate_rad_s > 0.0 ? vehicle.heading.fin_rate_rad_s : 1e9;
  const std::size_t n = t.row_time_s.size();
  std::vector<double> predicted(n, kNaN);
  // The rows where an unlogged command has acted since the row before.
  std::vector<unsigned char> anchored(n, 0);
  for (double u : unlogged) {
    const auto r = static_cast<std::size_t>(std::upper_bound(t.row_time_s.begin(), t.row_time_s.end(), u + delay) -
                                            t.row_time_s.begin());
    if (r < n) anchored[r] = 1;
  }
  double fin = kNaN;
  double command = 0.0;
  std::size_t next_command = 0;  // first row whose command has not acted yet
  // Moves the fin to `until`, switching to each command exactly when it
  // acts (row time + dead time): the prediction is continuous in the delay.
  double clock = t.row_time_s.empty() ? 0.0 : t.row_time_s.front();
  auto advance = [&](double until) {
    while (true) {
      const bool switch_first = next_command < n && t.row_time_s[next_command] + delay < until;
      const double to = switch_first ? std::max(clock, t.row_time_s[next_command] + delay) : until;
      if (std::isfinite(fin)) fin += std::clamp(command - fin, -rate * (to - clock), rate * (to - clock));
      clock = to;
      if (!switch_first) return;
      const double wanted = t.row_fin_command_rad[next_command];
      if (std::isfinite(wanted) && !(std::isfinite(fin) && std::abs(wanted - fin) <= deadband)) command = wanted;
      ++next_command;
    }
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double now = t.row_time_s[i];
    const bool continuous = i > 0 && std::isfinite(fin) && now - t.row_time_s[i - 1] <= t.max_gap_s;
    advance(now);
    if (continuous) predicted[i] = fin;
    if (anchored[i] != 0 && std::isfinite(t.row_fin_rad[i])) {
      // Where the fin rests is where its target is (or within the deadband
      // of it): the unlogged command's place, as near as the log tells.
      fin = command = t.row_fin_rad[i];
      if (continuous) predicted[i] = fin;
    } else if (!continuous) {
      fin = t.row_fin_rad[i];
    }
  }
  pick(predicted, rows, out);
}

// Slocum's law replayed on the logged heading: the error and rate are read
// a delay before each command; the integrator runs from the log's start and
// is held while the fin is centred (surface, turns), as the firmware's. The
// law steps at every cycle, logged or not: a gap of k cycles between two
// rows (a glider does not log every cycle; the independent truth drops 2 %)
// - k cycles within the cycle's own jitter - is stepped k times on the heading interpolated between them. Stepped once
// over the gap, the integrator takes the later error for the whole gap and
// the rate the gap's mean: in a turn, with the error a radian and the fin at
// its limit, a few hundredths of a radian of integrator gained or lost that
// show only when the fin leaves its limit, and stay (docs/science.md "The
// autopilot replay's unlogged dive start, and the truth's nominal cycle").
AutopilotLaw AutopilotLaw::from(const HeadingValues& values, const AutopilotSettings& settings, double fin_max_rad) {
  AutopilotLaw law;
  law.kp = value(values, HeadingEffect::kAutopilotGain);
  law.ki = value(values, HeadingEffect::kAutopilotIntegral);
  law.kd = value(values, HeadingEffect::kAutopilotDgain);
  law.hold_below = std::abs(value(values, HeadingEffect::kAutopilotDeadband));
  law.rate_deadband = settings.rate_deadband_rad_s;
  law.fin_max = fin_max_rad;
  return law;
}

namespace {

// The log's cycle: the median interval between rows where the law steps,
// and half the spread of those intervals (5th to 95th percentile of the
// ones under 1.5 cycles): the cycle's own jitter. Zero where there are none.
struct LoggedCycle {
  double cycle_s = 0.0, half_spread_s = 0.0;
};
LoggedCycle logged_cycle(const HeadingTrack& t) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < t.row_time_s.size(); ++i) {
    const bool both = std::isfinite(t.row_command_rad[i]) && t.row_gliding[i] &&
                      std::isfinite(t.row_command_rad[i - 1]) && t.row_gliding[i - 1];
    if (both && t.row_time_s[i] > t.row_time_s[i - 1]) dt.push_back(t.row_time_s[i] - t.row_time_s[i - 1]);
  }
  if (dt.empty()) return {};
  std::sort(dt.begin(), dt.end());
  LoggedCycle c;
  c.cycle_s = dt[dt.size() / 2];
  const auto regular = static_cast<std::size_t>(std::upper_bound(dt.begin(), dt.end(), 1.5 * c.cycle_s) - dt.begin());
  const auto at = [&](double q) { return dt[static_cast<std::size_t>(q * static_cast<double>(regular - 1))]; };
  c.half_spread_s = 0.5 * (at(0.95) - at(0.05));
  return c;
}

// Cycles the law stepped between two rows dt apart: k where dt is k cycles
// within k times the cycle's own jitter (the sum of k jittered cycles), else
// 1 - a longer cycle, not unlogged ones (the real comet logs' few gaps are
// 1.5-3.4 cycles, off a whole number by 2-10 times their jitter). At most
// this many (a longer gap is a stop).
constexpr int kMaxCyclesPerGap = 8;
int cycles_between(double dt, const LoggedCycle& c) {
  if (!(c.cycle_s > 0.0) || !(dt > 1.5 * c.cycle_s)) return 1;
  const long k = std::lround(dt / c.cycle_s);
  if (k > kMaxCyclesPerGap ||
      std::abs(dt - static_cast<double>(k) * c.cycle_s) > static_cast<double>(k) * c.half_spread_s) {
    return 1;
  }
  return static_cast<int>(k);
}

}  // namespace

std::vector<double> unlogged_cycle_times(const HeadingTrack& t) {
  const LoggedCycle cycle = logged_cycle(t);
  std::vector<double> times;
  for (std::size_t i = 1; i < t.row_time_s.size(); ++i) {
    const double dt = t.row_time_s[i] - t.row_time_s[i - 1];
    if (dt > t.max_gap_s) continue;  // a stop: the replay starts again after it
    const int k = cycles_between(dt, cycle);
    for (int j = 1; j < k; ++j) times.push_back(t.row_time_s[i - 1] + dt * j / k);
  }
  return times;
}

AutopilotReplay::AutopilotReplay(const HeadingTrack& track, const AutopilotSettings& settings, AutopilotClock clock)
    : track_(track), settings_(settings), clock_(clock) {
  const LoggedCycle c = logged_cycle(track);
  cycle_s_ = c.cycle_s;
  half_spread_s_ = c.half_spread_s;
  // Where the log holds a command change between two consecutive cycles
  // the change happened at the later row's depth: the change depth lies
  // between the two rows' depths. Every such change must move the same way
  // and their brackets overlap, else the command does not change at one
  // depth (a waypoint reached, an operator's new heading) and an unlogged
  // cycle keeps the earlier command.
  const std::vector<double>& z = track.row_depth_m;
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  int direction = 0;
  bool one_depth = true;
  for (std::size_t i = 1; i < track.row_time_s.size() && one_depth && cycle_s_ > 0.0; ++i) {
    const double before = track.row_command_rad[i - 1], after = track.row_command_rad[i];
    const bool gliding = track.row_gliding[i] && track.row_gliding[i - 1];
    const double gap = track.row_time_s[i] - track.row_time_s[i - 1];
    if (!gliding || !std::isfinite(before) || !std::isfinite(after) || before == after || gap > 1.5 * cycle_s_)
      continue;
    if (!std::isfinite(z[i]) || !std::isfinite(z[i - 1]) || z[i] == z[i - 1]) {
      one_depth = false;
      break;
    }
    const int way = z[i] > z[i - 1] ? 1 : -1;
    if (direction != 0 && way != direction) one_depth = false;
    direction = way;
    lo = std::max(lo, std::min(z[i], z[i - 1]));
    hi = std::min(hi, std::max(z[i], z[i - 1]));
  }
  if (one_depth && direction != 0 && lo <= hi) {
    change_depth_lo_m_ = lo;
    change_depth_hi_m_ = hi;
    change_direction_ = direction;
  }
  // What inputs() reads at every delay, worked out once: where the law
  // steps, the cycles in each row's gap, the rows' spans and heading steps.
  const std::size_t n = track.row_time_s.size();
  active_.resize(n);
  gap_cycles_.assign(n, 1);
  row_span_.assign(n, kNaN);
  heading_step_.assign(n, kNaN);
  for (std::size_t i = 0; i < n; ++i) {
    active_[i] = std::isfinite(track.row_command_rad[i]) && track.row_gliding[i];
    if (i > 0) gap_cycles_[i] = cycles_between(track.row_time_s[i] - track.row_time_s[i - 1], c);
    max_steps_ += static_cast<std::size_t>(gap_cycles_[i]);
    if (i + 1 < n) {
      row_span_[i] = track.row_time_s[i + 1] - track.row_time_s[i];
      heading_step_[i] = wrap_pi(track.row_heading_rad[i + 1] - track.row_heading_rad[i]);
    }
  }
}

// The command at an unlogged cycle `fraction` of the way from row - 1 to
// row: the earlier row's, unless the command changed across the gap and the
// depth (interpolated) had passed the log's change depth by then - the
// cycle where a dive starts is unlogged, and the new heading's error (a
// radian) ran the integrator there.
double AutopilotReplay::unlogged_command(std::size_t row, double fraction) const {
  const double before = track_.row_command_rad[row - 1], after = track_.row_command_rad[row];
  if (before == after || change_direction_ == 0) return before;
  const std::vector<double>& z = track_.row_depth_m;
  const double depth = z[row - 1] + fraction * (z[row] - z[row - 1]);
  const double change = 0.5 * (change_depth_lo_m_ + change_depth_hi_m_);
  const bool passed = change_direction_ < 0 ? depth <= change : depth >= change;
  return passed ? after : before;
}

AutopilotReplay::Inputs& AutopilotReplay::inputs(double delay) {
  for (Inputs& cached : cache_) {
    if (cached.delay == delay) return cached;
  }
  // The oldest delay's buffers take the new one's (no allocation); its
  // integrators were that delay's.
  if (cache_.size() >= kCachedDelays) std::rotate(cache_.begin(), cache_.begin() + 1, cache_.end());
  if (cache_.size() < kCachedDelays) cache_.emplace_back();
  Inputs& made = cache_.back();
  made.delay = delay;
  for (IntegratorSeries& series : made.integrators) series.valid = false;
  // Room for every step the rows can take (the unlogged cycles' at most),
  // cut to the steps taken at the end.
  made.error.resize(max_steps_);
  made.rate.resize(max_steps_);
  made.dt.resize(max_steps_);
  made.still.resize(max_steps_);
  made.row.resize(max_steps_);
  std::size_t steps = 0;
  const HeadingTrack& t = track_;
  const std::size_t n = t.row_time_s.size();
  made.kind.resize(n);
  made.step_end.resize(n);
  const std::span<const double> time(t.row_time_s);
  const std::vector<double>& heading_at = t.row_heading_rad;
  double last_heading = kNaN;
  // The heading read a delay before `at`, linear between rows (across the
  // shorter way round); NaN before the log's start, after its end, across
  // a NaN. The
  // reads go forward in time, so the first row after each is found from
  // the last one's (the same row std::upper_bound finds, without its
  // search: the search was a third of a heading diagnosis).
  std::size_t after = 0;
  auto read = [&](double at) {
    const double when = at - delay;
    if (std::isnan(when) || (after > 0 && !(time[after - 1] <= when))) {
      after = static_cast<std::size_t>(std::upper_bound(time.begin(), time.end(), when) - time.begin());
    }
    while (after < n && time[after] <= when) ++after;
    if (after == 0) return kNaN;
    const std::size_t j = after - 1;
    if (j + 1 >= n) return time[j] == when ? heading_at[j] : kNaN;
    return heading_at[j] + (when - time[j]) / row_span_[j] * heading_step_[j];
  };
  const double rate_deadband = settings_.rate_deadband_rad_s;
  // One law step for `row`: the rate read against the rate deadband.
  auto add_step = [&](std::size_t row, double error, double rate, double dt) {
    const bool still = std::abs(rate) < rate_deadband;
    made.error[steps] = error;
    made.rate[steps] = still ? 0.0 : rate;
    made.dt[steps] = dt;
    made.still[steps] = still ? 1 : 0;
    made.row[steps] = row;
    ++steps;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (!active_[i]) {
      last_heading = kNaN;  // the fin is centred: the rate estimate restarts, the integrator is kept
      made.kind[i] = RowKind::kCentre;
      made.step_end[i] = steps;
      continue;
    }
    const double heading = read(time[i]);
    // The command is the current one (the mission sets it, nothing delays
    // it); only the heading is read late.
    const double command = t.row_command_rad[i];
    if (!std::isfinite(heading)) {
      made.kind[i] = RowKind::kNone;
      made.step_end[i] = steps;
      continue;
    }
    const double gap = i > 0 ? time[i] - time[i - 1] : 0.0;
    // The unlogged cycles before this row, where the previous row's law ran on.
    const int cycles = std::isfinite(last_heading) ? gap_cycles_[i] : 1;
    // Each step's interval: its share of the gap, or the log's cycle.
    const bool nominal = clock_ == AutopilotClock::kNominal && cycle_s_ > 0.0;
    const double spacing = gap / cycles;  // when the unlogged cycles read the heading
    const double dt = nominal ? cycle_s_ : spacing;
    for (int m = 1; m < cycles; ++m) {
      const double h = read(time[i - 1] + m * spacing);
      add_step(i, wrap_pi(unlogged_command(i, static_cast<double>(m) / cycles) - h), wrap_pi(h - last_heading) / dt,
               dt);
      last_heading = h;
    }
    add_step(i, wrap_pi(command - heading),
             std::isfinite(last_heading) && dt > 0.0 ? wrap_pi(heading - last_heading) / dt : 0.0, dt);
    made.kind[i] = RowKind::kStep;
    made.step_end[i] = steps;
    last_heading = heading;
  }
  made.error.resize(steps);
  made.rate.resize(steps);
  made.dt.resize(steps);
  made.still.resize(steps);
  made.row.resize(steps);
  return made;
}

// The integrator after each of the delay's steps for this integral gain,
// as AutopilotLaw::step_read sums it where the law never holds: the last
// two gains' kept per delay.
const std::vector<double>& AutopilotReplay::integrator(Inputs& in, double ki) {
  const auto bits = std::bit_cast<std::uint64_t>(ki);
  for (const IntegratorSeries& series : in.integrators) {
    if (series.valid && series.ki_bits == bits) return series.after_step;
  }
  IntegratorSeries& series = in.integrators[in.next_integrator];
  in.next_integrator = (in.next_integrator + 1) % in.integrators.size();
  series.valid = true;
  series.ki_bits = bits;
  series.after_step.resize(in.error.size());
  double sum = 0.0;  // AutopilotLaw's integrator, from the log's start
  for (std::size_t s = 0; s < in.error.size(); ++s) {
    sum += ki * in.error[s] * in.dt[s];
    series.after_step[s] = sum;
  }
  return series.after_step;
}

void AutopilotReplay::predict(const HeadingValues& values, std::span<const std::size_t> rows,
                              std::vector<double>& out) {
  // The law reads these effects alone; a fit asks again for the values it
  // last asked for (its fit and held-out rows, a step it did not take):
  // the last replay answers, same bits.
  std::array<std::uint64_t, kLawEffects.size()> law_bits{};
  for (std::size_t k = 0; k < law_bits.size(); ++k)
    law_bits[k] = std::bit_cast<std::uint64_t>(value(values, kLawEffects[k]));
  if (replayed_ && law_bits == replayed_law_) {
    pick(predicted_, rows, out);
    return;
  }
  replay(values);
  replayed_law_ = law_bits;
  replayed_ = true;
  pick(predicted_, rows, out);
}

void AutopilotReplay::replay(const HeadingValues& values) {
  Inputs& in = inputs(std::abs(value(values, HeadingEffect::kAutopilotDelay)));
  AutopilotLaw law = AutopilotLaw::from(values, settings_, track_.fin_max_rad);
  const std::size_t n = in.kind.size();
  predicted_.assign(n, kNaN);
  if (!(law.hold_below > 0.0)) {
    // The law never holds (|error| < 0 is never true): the integrator is
    // the steps' running sum whatever the gains on the output, and each
    // step's output reads it (AutopilotLaw::step_read's sums, in its
    // order); a row's last step's output stands.
    const std::vector<double>& integrated = integrator(in, law.ki);
    for (std::size_t s = 0; s < in.error.size(); ++s) {
      predicted_[in.row[s]] =
          std::clamp(law.kp * in.error[s] + integrated[s] + law.kd * in.rate[s], -law.fin_max, law.fin_max);
    }
    return;
  }
  std::size_t s = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (in.kind[i] == RowKind::kCentre) {
      law.output = 0.0;
    } else if (in.kind[i] == RowKind::kStep) {
      for (; s < in.step_end[i]; ++s) law.step_read(in.error[s], in.rate[s], in.still[s] != 0, in.dt[s]);
      predicted_[i] = law.output;
    }
  }
}

void predict_autopilot_fin(const HeadingTrack& t, const AutopilotSettings& settings, const HeadingValues& values,
                           std::span<const std::size_t> rows, std::vector<double>& out) {
  AutopilotReplay(t, settings).predict(values, rows, out);
}

namespace {

// The yaw model's values for one set of effects: where the yaw rate relaxes
// to at sample interval k (w: the fraction of it, now: the time) on a glide
// rolled `roll`, and how fast.
struct YawPlant {
  const HeadingTrack& t;
  const model::HeadingModel& hd;
  double delay, fin_gain, roll_offset, tau, fin_rate;
  double fin_dead_time;  // the servo's (its link's finding): when the fin leaves a reading
  double roll_turn;      // the roll's turn over the vehicle file's (roll_turn_per_lift)
  YawPlant(const HeadingTrack& track, const model::VehicleParams& vehicle, const HeadingValues& values)
      : t(track),
        hd(vehicle.heading),
        delay(std::abs(value(values, HeadingEffect::kYawDelay))),
        fin_gain(vehicle.heading.fin_yaw_gain_per_m * value(values, HeadingEffect::kFinEffectiveness)),
        roll_offset(value(values, HeadingEffect::kRollOffset)),
        tau(std::max(0.05, std::abs(value(values, HeadingEffect::kYawTimeConstant)))),
        fin_rate(vehicle.heading.fin_rate_rad_s > 0.0 ? vehicle.heading.fin_rate_rad_s : 1e9),
        fin_dead_time(std::abs(value(values, HeadingEffect::kFinDelay))),
        roll_turn(roll_turn_per_lift(value(values, HeadingEffect::kLiftFactor))),
        fast(yaw_fast_pole(track, delay)) {}
  double fast;  // the yaw's fast pole (s; 0: none): yaw_fast_pole
  // The roll as logged between samples k and k + 1, with the offset: the
  // fin rolls the glider and the roll turns it back against the fin (the
  // independent truth's 0-0.2 rad of roll per rad of fin read as a fin
  // 0.84-0.88 where the glide's median roll stood for it; docs/science.md
  // "The yaw's lag in a closed loop and the fin's roll"). The closed loop,
  // which flies its own fin, keeps the median (HeadingTrack::roll_rad).
  double roll_at(std::size_t k, double w) const {
    return t.roll_sample_rad[k] + w * (t.roll_sample_rad[k + 1] - t.roll_sample_rad[k]) + roll_offset;
  }
  double target(std::size_t k, double w, double now) const {
    const double speed = t.speed_m_s[k] + w * (t.speed_m_s[k + 1] - t.speed_m_s[k]);
    const double lift = t.lift_factor[k] + w * (t.lift_factor[k + 1] - t.lift_factor[k]);
    const double roll = roll_at(k, w);
    const double fin = fin_between_rows(t.row_time_s, t.row_fin_filled_rad, now - delay, fin_rate, fin_dead_time);
    return speed *
           (fin_gain * (std::isfinite(fin) ? fin : 0.0) + hd.roll_yaw_gain_per_m * roll_turn * lift * std::sin(roll));
  }
};

}  // namespace

double roll_turn_per_lift(double lift_factor) { return 1.0 / std::max(0.05, std::abs(lift_factor)); }

double carried_fast_pole(double prior_centre_s, double yaw_delay_s) {
  return yaw_delay_s > 0.0 ? std::min(prior_centre_s, yaw_delay_s) : 0.0;
}

double yaw_fast_pole(const HeadingTrack& track, double yaw_delay_s) {
  return track.yaw_fast_pole_with_lag_s > 0.0 ? track.yaw_fast_pole_with_lag_s
                                              : carried_fast_pole(track.yaw_fast_pole_s, yaw_delay_s);
}

double fast_pole_step(double& lead, double goal, double h, double tau, double p, double a, double b) {
  if (!(p > 0.0)) {
    lead = goal;
    return 0.0;
  }
  const double held = lead - goal;
  lead = goal + held * b;
  // e_y(h) = e_y(0) a + held p / (p - tau) (b - a); its limit where p = tau.
  if (std::abs(p - tau) < 1e-6 * tau) return held * (h / tau) * a;
  return held * p / (p - tau) * (b - a);
}

// The model's yaw (dynamics.hpp): the yaw rate relaxes toward
// V (fin_gain eff fin(t - delay) + roll_gain a_eff sin(roll + offset)),
// from the run's first heading and the steady rate there; its heading goes
// through the measured yaw rate's estimator.
void predict_yaw_rate(const HeadingTrack& t, const model::VehicleParams& vehicle, const HeadingValues& values,
                      std::span<const std::size_t> samples, std::vector<double>& out) {
  const YawPlant plant(t, vehicle, values);
  const double tau = plant.tau;
  const StepDecay decay(tau, kStepS), fast_decay(plant.fast, kStepS);
  std::vector<double> rate(t.size(), kNaN);
  std::vector<double> model_heading;
  std::size_t wanted = 0;
  for (std::size_t run = 0; run < t.run_first.size(); ++run) {
    const std::size_t first = t.run_first[run], end = t.run_end(run);
    if (wanted >= samples.size()) break;
    if (samples[wanted] >= end) continue;
    auto target = [&](std::size_t k, double w, double now) { return plant.target(k, w, now); };
    model_heading.assign(1, t.heading_rad[first]);
    double yaw_rate = target(first, 0.0, t.time_s[first]);
    double lead = yaw_rate;  // the fast pole's state: steady at the start
    double psi = t.heading_rad[first];
    for (std::size_t k = first; k + 1 < end; ++k) {
      double s = t.time_s[k];
      const double span = t.time_s[k + 1] - s;
      while (s < t.time_s[k + 1]) {
        const double h = std::min(kStepS, t.time_s[k + 1] - s);
        const double goal = target(k, (s + 0.5 * h - t.time_s[k]) / span, s + 0.5 * h);
        const double a = decay(h);
        const double next =
            goal + (yaw_rate - goal) * a + fast_pole_step(lead, goal, h, tau, plant.fast, a, fast_decay(h));
        psi += 0.5 * h * (yaw_rate + next);
        yaw_rate = next;
        s += h;
      }
      model_heading.push_back(psi);
    }
    const flightlog::Column slope = depth_rate_estimate(std::span<const double>(t.time_s.data() + first, end - first),
                                                        model_heading, t.rate_half_window_s, t.max_gap_s);
    std::copy(slope.begin(), slope.end(), rate.begin() + static_cast<long>(first));
    while (wanted < samples.size() && samples[wanted] < end) ++wanted;
  }
  pick(rate, samples, out);
}

namespace {

// The filter over every glide: the innovations per second at each sample
// (NaN at a glide's first) and, if asked, the innovations' variances (rad^2).
void filter_headings(const HeadingTrack& t, const model::VehicleParams& vehicle, const HeadingValues& values,
                     const YawNoise& noise, std::vector<double>& innovation, std::vector<double>* variance) {
  const YawPlant plant(t, vehicle, values);
  const double tau = plant.tau;
  const double tau_d = std::max(1.0, noise.correlation_s);
  const StepDecay decay(tau, kStepS), fast_decay(plant.fast, kStepS), random_decay(tau_d, kStepS);
  const double var_d = noise.disturbance_rad_s * noise.disturbance_rad_s;
  // The compass's noise, at least the heading's rounding (a zero variance
  // would make the filter trust a reading exactly).
  const double var_n = std::max(noise.heading_rad * noise.heading_rad, 1e-8);
  innovation.assign(t.size(), kNaN);
  if (variance != nullptr) variance->assign(t.size(), kNaN);
  for (std::size_t run = 0; run < t.run_first.size(); ++run) {
    const std::size_t first = t.run_first[run], end = t.run_end(run);
    auto target = [&](std::size_t k, double w, double now) { return plant.target(k, w, now); };
    // The state from sample k to k + 1: the mean as predict_yaw_rate steps it
    // (the yaw rate relaxing toward fin + roll + random yaw, the heading by
    // the trapezoid), the random yaw decaying, and (P not null) the
    // covariance by its linearisation.
    // The fast pole's state (`lead`) is the logged inputs' alone: carried
    // beside the filter's, no variance of its own.
    double lead = 0.0;
    auto step = [&](Eigen::Vector3d& x, std::size_t k, Eigen::Matrix3d* P) {
      double s = t.time_s[k];
      const double span = t.time_s[k + 1] - s;
      while (s < t.time_s[k + 1]) {
        const double h = std::min(kStepS, t.time_s[k + 1] - s);
        const double u = target(k, (s + 0.5 * h - t.time_s[k]) / span, s + 0.5 * h);
        const double a = decay(h), phi = random_decay(h);
        const double held = fast_pole_step(lead, u, h, tau, plant.fast, a, fast_decay(h));
        Eigen::Matrix3d F;
        F << 1.0, 0.5 * h * (1.0 + a), 0.5 * h * (1.0 - a), 0.0, a, 1.0 - a, 0.0, 0.0, phi;
        x = F * x + Eigen::Vector3d(0.5 * h * (1.0 - a) * u + 0.5 * h * held, (1.0 - a) * u + held, 0.0);
        if (P != nullptr) {
          *P = F * *P * F.transpose();
          (*P)(2, 2) += var_d * (1.0 - phi * phi);
        }
        s += h;
      }
    };
    // From the glide's first reading and its measured rate.
    Eigen::Vector3d x(t.heading_rad[first], std::isfinite(t.yaw_rate_rad_s[first]) ? t.yaw_rate_rad_s[first] : 0.0,
                      0.0);
    Eigen::Matrix3d P = Eigen::Vector3d(var_n, 4.0 * var_d + 1e-8, var_d).asDiagonal();
    lead = target(first, 0.0, t.time_s[first]);
    for (std::size_t k = first; k + 1 < end; ++k) {
      step(x, k, &P);
      // The next reading: the innovation, then the update.
      const std::size_t j = k + 1;
      const double nu = x[0] - t.heading_rad[j];
      innovation[j] = nu / (t.time_s[j] - t.time_s[k]);
      const double S = P(0, 0) + var_n;
      if (variance != nullptr) (*variance)[j] = S;
      const Eigen::Vector3d gain = P.col(0) / S;
      x -= gain * nu;
      const Eigen::RowVector3d heading_row = P.row(0);
      P -= gain * heading_row;
    }
  }
}

}  // namespace

void heading_innovations(const HeadingTrack& t, const model::VehicleParams& vehicle, const HeadingValues& values,
                         const YawNoise& noise, std::span<const std::size_t> samples, std::vector<double>& out) {
  std::vector<double> innovation;
  filter_headings(t, vehicle, values, noise, innovation, nullptr);
  pick(innovation, samples, out);
}

double innovations_cost(const HeadingTrack& t, const model::VehicleParams& vehicle, const HeadingValues& values,
                        const YawNoise& noise, std::span<const std::size_t> samples) {
  std::vector<double> innovation, variance;
  filter_headings(t, vehicle, values, noise, innovation, &variance);
  double sum = 0.0;
  std::size_t n = 0;
  for (const std::size_t k : samples) {
    if (k == 0 || !std::isfinite(innovation[k]) || !std::isfinite(variance[k]) || variance[k] <= 0.0) continue;
    const double nu = innovation[k] * (t.time_s[k] - t.time_s[k - 1]);
    sum += std::log(variance[k]) + nu * nu / variance[k];
    ++n;
  }
  return n > 0 ? sum : std::numeric_limits<double>::infinity();
}

YawNoise fit_yaw_noise(const HeadingTrack& t, const model::VehicleParams& vehicle, const HeadingValues& values,
                       const YawNoise& start, std::span<const std::size_t> samples, bool grid) {
  // -2 log likelihood of the innovations (Gaussian): a grid around the start
  // (the compass noise x1/4..x4, the random yaw's RMS 1e-4..2e-2 rad/s, its
  // correlation 10-300 s), then each of the three refined by factors down to
  // 4 % (the filter's mean does not depend on them, the innovations'
  // whiteness does: a compass noise read 40 % high left the fin 20 % weak
  // on a SIL log).
  auto cost = [&](const YawNoise& trial) { return innovations_cost(t, vehicle, values, trial, samples); };
  YawNoise best = start;
  double best_cost = grid ? std::numeric_limits<double>::infinity() : cost(start);
  for (const double noise_scale : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    if (!grid) break;
    for (int i = 0; i <= 10; ++i) {
      for (const double correlation : {10.0, 30.0, 100.0, 300.0}) {
        YawNoise trial = start;
        trial.heading_rad = std::max(start.heading_rad, 1e-4) * noise_scale;
        trial.disturbance_rad_s = 1e-4 * std::pow(200.0, i / 10.0);
        trial.correlation_s = correlation;
        if (const double c = cost(trial); c < best_cost) {
          best_cost = c;
          best = trial;
        }
      }
    }
  }
  for (const double factor : {1.4, 1.18, 1.08, 1.04}) {
    for (double YawNoise::*field : {&YawNoise::heading_rad, &YawNoise::disturbance_rad_s, &YawNoise::correlation_s}) {
      for (const double f : {factor, 1.0 / factor}) {
        YawNoise trial = best;
        trial.*field *= f;
        if (const double c = cost(trial); c < best_cost) {
          best_cost = c;
          best = trial;
        }
      }
    }
  }
  return best;
}

}  // namespace glider::diagnose
