// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/heading_closed_loop.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>
#include <random>
#include <span>

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kStepS = 0.25;  // the plant's integration step (s), as the yaw replay's

double wrap_pi(double a) { return std::remainder(a, 2.0 * std::numbers::pi); }

std::size_t row_at_or_before(std::span<const double> time, double t) {
  const auto it = std::upper_bound(time.begin(), time.end(), t);
  return it == time.begin() ? SIZE_MAX : static_cast<std::size_t>(it - time.begin()) - 1;
}

// A series recorded along the flight, read back at an earlier time (before
// its first point: its first value).
struct History {
  std::vector<double> time, value;
  void add(double t, double x) {
    time.push_back(t);
    value.push_back(x);
  }
  double at(double t) const {
    const std::size_t j = row_at_or_before(time, t);
    if (j == SIZE_MAX) return value.front();
    if (j + 1 >= time.size()) return value.back();
    const double w = (t - time[j]) / (time[j + 1] - time[j]);
    return value[j] + w * (value[j + 1] - value[j]);
  }
};

// The autopilot's state carried from cycle to cycle: Slocum's law (the same
// AutopilotLaw as predict_autopilot_fin's), reading the model's heading.
struct Autopilot {
  AutopilotLaw law;
  double last_read = kNaN, last_time = kNaN;
  // The fin commanded at `now` from the heading `read` and the command.
  double cycle(double now, double read, double command) {
    const double error = wrap_pi(command - read);
    const double dt = std::isfinite(last_time) ? now - last_time : 0.0;
    const double rate = std::isfinite(last_read) && dt > 0.0 ? wrap_pi(read - last_read) / dt : 0.0;
    last_read = read;
    last_time = now;
    return law.step(error, rate, dt);
  }
};

}  // namespace

std::vector<ClosedLoopGlide> fly_closed_loop(const HeadingTrack& t, const model::VehicleParams& vehicle,
                                             const AutopilotSettings& settings, const HeadingValues& values,
                                             const ShearProfile* shear, const ClosedLoopOptions& options) {
  const model::HeadingModel& hd = vehicle.heading;
  const double fin_delay = std::abs(at(values, HeadingEffect::kFinDelay));
  const double fin_deadband = std::abs(at(values, HeadingEffect::kFinDeadband));
  const double yaw_delay = std::abs(at(values, HeadingEffect::kYawDelay));
  const double fin_gain = hd.fin_yaw_gain_per_m * at(values, HeadingEffect::kFinEffectiveness);
  const double roll_offset = at(values, HeadingEffect::kRollOffset);
  const double roll_turn = roll_turn_per_lift(at(values, HeadingEffect::kLiftFactor));
  const double tau = std::max(0.05, std::abs(at(values, HeadingEffect::kYawTimeConstant)));
  const double fast_pole = yaw_fast_pole(t, yaw_delay);
  const StepDecay decay(tau, kStepS), fast_decay(fast_pole, kStepS);
  const double fin_rate = hd.fin_rate_rad_s > 0.0 ? hd.fin_rate_rad_s : 1e9;
  const double autopilot_delay = std::abs(at(values, HeadingEffect::kAutopilotDelay));
  Autopilot autopilot{AutopilotLaw::from(values, settings, t.fin_max_rad)};
  std::mt19937 random(options.seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  const std::span<const double> row_time(t.row_time_s);
  const std::size_t rows = t.row_time_s.size();
  auto command_at = [&](double when) {
    const std::size_t r = row_at_or_before(row_time, when);
    return r == SIZE_MAX ? kNaN : t.row_command_rad[r];
  };

  std::vector<ClosedLoopGlide> out;
  std::size_t scored = 0;
  for (std::size_t run = 0; run < t.run_first.size(); ++run) {
    const std::size_t first = t.run_first[run], end = t.run_end(run);
    while (scored < t.scored.size() && t.scored[scored] < first) ++scored;
    if (scored >= t.scored.size() || t.scored[scored] >= end) continue;
    const double start = t.time_s[first];
    const std::size_t r0 = row_at_or_before(row_time, start);
    if (r0 == SIZE_MAX) continue;
    // The glide starts from the log's state: its heading, fin and last command.
    double fin = std::isfinite(t.row_fin_filled_rad[r0]) ? t.row_fin_filled_rad[r0] : 0.0;
    double servo_command = fin;
    autopilot.law.output = std::isfinite(t.row_fin_command_rad[r0]) ? t.row_fin_command_rad[r0] : fin;
    autopilot.last_read = kNaN;
    autopilot.last_time = kNaN;
    std::deque<std::pair<double, double>> pending;  // (when it acts, command)
    History heading, fin_history;
    double psi = t.heading_rad[first];
    heading.add(start, psi);
    fin_history.add(start, fin);
    const double roll = t.roll_rad[first] + roll_offset;
    auto goal = [&](std::size_t k, double w, double now) {
      const double speed = t.speed_m_s[k] + w * (t.speed_m_s[k + 1] - t.speed_m_s[k]);
      const double lift = t.lift_factor[k] + w * (t.lift_factor[k + 1] - t.lift_factor[k]);
      const double f = yaw_delay > 0.0 ? fin_history.at(now - yaw_delay) : fin;
      const double from_shear = shear != nullptr ? shear_at(*shear, t.depth_m[k]) * shear_yaw_per_unit(t, k) : 0.0;
      return speed * (fin_gain * f + hd.roll_yaw_gain_per_m * roll_turn * lift * std::sin(roll)) + from_shear;
    };
    std::vector<double> simulated(end - first, kNaN);
    simulated[0] = psi;
    double yaw_rate = first + 1 < end ? goal(first, 0.0, start) : 0.0;
    double lead = yaw_rate;  // the yaw's fast pole (heading_models.hpp fast_pole_step): steady at the start
    std::size_t next_row = r0 + 1;
    const double scored_from = t.time_s[t.scored[scored]];
    double travel = 0.0;
    for (std::size_t k = first; k + 1 < end; ++k) {
      double s = t.time_s[k];
      const double span = t.time_s[k + 1] - s;
      while (s < t.time_s[k + 1]) {
        // The autopilot's cycles due by now, each reading the model's
        // heading a delay before (the log's before the glide), then the
        // servo's commands due.
        while (next_row < rows && row_time[next_row] <= s) {
          const double now = row_time[next_row++];
          const double when = now - autopilot_delay;
          const double read =
              (when <= start ? t.heading_rad[first] : heading.at(when)) + options.heading_noise_rad * noise(random);
          const double command = command_at(now);  // only the heading is read late (heading_models.cpp)
          if (!std::isfinite(command)) continue;
          const double previous = autopilot.law.output;
          pending.emplace_back(now + fin_delay, autopilot.cycle(now, read, command));
          if (now >= scored_from) travel += std::abs(autopilot.law.output - previous);
        }
        while (!pending.empty() && pending.front().first <= s) {
          if (std::abs(pending.front().second - fin) > fin_deadband) servo_command = pending.front().second;
          pending.pop_front();
        }
        const double h = std::min(kStepS, t.time_s[k + 1] - s);
        fin += std::clamp(servo_command - fin, -fin_rate * h, fin_rate * h);
        const double target = goal(k, (s + 0.5 * h - t.time_s[k]) / span, s + 0.5 * h);
        const double a = decay(h);
        const double next =
            target + (yaw_rate - target) * a + fast_pole_step(lead, target, h, tau, fast_pole, a, fast_decay(h));
        psi += 0.5 * h * (yaw_rate + next);
        yaw_rate = next;
        s += h;
        heading.add(s, psi);
        fin_history.add(s, fin);
      }
      simulated[k + 1 - first] = psi;
    }
    ClosedLoopGlide g;
    g.run = run;
    g.yo = t.yo[first];
    g.dive = t.phase[first] == flightlog::Phase::kDive;
    double sim = 0.0, logged = 0.0;
    std::size_t n = 0;
    for (; scored < t.scored.size() && t.scored[scored] < end; ++scored) {
      const std::size_t k = t.scored[scored];
      const double command = command_at(t.time_s[k]);
      if (!std::isfinite(command) || !std::isfinite(simulated[k - first])) continue;
      sim += wrap_pi(command - simulated[k - first]);
      logged += wrap_pi(command - t.heading_rad[k]);
      ++n;
    }
    if (n == 0) continue;
    // The log's c_fin steps over the same time.
    const double scored_to = t.time_s[end - 1];
    double logged_travel = 0.0, last = kNaN;
    for (std::size_t r = r0; r < rows && row_time[r] <= scored_to; ++r) {
      if (row_time[r] < scored_from || !std::isfinite(t.row_fin_command_rad[r])) continue;
      if (std::isfinite(last)) logged_travel += std::abs(t.row_fin_command_rad[r] - last);
      last = t.row_fin_command_rad[r];
    }
    const double duration = std::max(1.0, scored_to - scored_from);
    g.simulated_fin_travel_rad_s = travel / duration;
    g.logged_fin_travel_rad_s = logged_travel / duration;
    g.simulated_error_rad = sim / static_cast<double>(n);
    g.logged_error_rad = logged / static_cast<double>(n);
    out.push_back(g);
  }
  return out;
}

}  // namespace glider::diagnose
