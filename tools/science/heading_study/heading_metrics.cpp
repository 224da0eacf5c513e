// SPDX-License-Identifier: Apache-2.0
#include "heading_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "glider/units.hpp"

namespace glider::heading_study {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

double wrap_deg(double rad) {
  const double two_pi = 2.0 * std::numbers::pi;
  return rad_to_deg(std::fmod(std::fmod(rad + std::numbers::pi, two_pi) + two_pi, two_pi) - std::numbers::pi);
}

// One glide's errors about their mean: amplitude and zero-crossing periods.
void glide_oscillation(const std::vector<double>& t, const std::vector<double>& e, std::vector<double>& amplitudes,
                       std::vector<double>& periods) {
  if (e.size() < 20) return;
  double mean = 0.0;
  for (double x : e) mean += x;
  mean /= static_cast<double>(e.size());
  double var = 0.0;
  for (double x : e) var += (x - mean) * (x - mean);
  amplitudes.push_back(std::sqrt(2.0 * var / static_cast<double>(e.size())));
  // Upward crossings with hysteresis: below mean - h, then above mean + h
  // (compass noise and the 1 Hz steps must not count as swings).
  constexpr double kHysteresisDeg = 2.0;
  double last_crossing = -1.0;
  bool below = false;
  for (std::size_t k = 0; k < e.size(); ++k) {
    if (e[k] - mean < -kHysteresisDeg) below = true;
    if (below && e[k] - mean > kHysteresisDeg) {
      below = false;
      if (last_crossing >= 0.0) periods.push_back(t[k] - last_crossing);
      last_crossing = t[k];
    }
  }
}

// The inflections' turns (see the header): index 0 dive -> climb, 1 climb -> dive.
void inflection_turns(const flightlog::FlightLog& log, double skip_s, HeadingMetrics& m) {
  const auto* pitch = log.find("m_pitch");
  const auto* roll = log.find("m_roll");
  if (pitch == nullptr || roll == nullptr || log.rows() == 0) return;
  constexpr double kBeforeS = 12.0, kAfterS = 35.0;
  const auto& time = log.time();
  const auto& heading = log.column("m_heading");
  const auto& state = log.column("m_depth_state");
  std::vector<double> turns[2], kinematic[2];
  for (std::size_t i = 0; i + 1 < log.rows(); ++i) {
    const bool dive_ends = state[i] == 1.0 && state[i + 1] != 1.0;
    const bool climb_ends = state[i] == 2.0 && state[i + 1] != 2.0;
    if (!(dive_ends || climb_ends) || time[i] - time[0] < skip_s) continue;
    double turn = 0.0, pitch_over = 0.0;
    bool complete = true;
    std::size_t k = i;
    while (k > 0 && time[i] - time[k - 1] <= kBeforeS) --k;
    for (; k + 1 < log.rows() && time[k + 1] - time[i] <= kAfterS; ++k) {
      const double values[] = {heading[k], heading[k + 1], (*pitch)[k], (*pitch)[k + 1], (*roll)[k], (*roll)[k + 1]};
      if (!std::all_of(std::begin(values), std::end(values), [](double v) { return std::isfinite(v); })) {
        complete = false;
        break;
      }
      turn += std::remainder(heading[k + 1] - heading[k], 2.0 * std::numbers::pi);
      const double mean_pitch = 0.5 * ((*pitch)[k] + (*pitch)[k + 1]);
      pitch_over +=
          ((*pitch)[k + 1] - (*pitch)[k]) * std::tan(0.5 * ((*roll)[k] + (*roll)[k + 1])) / std::cos(mean_pitch);
    }
    if (!complete) continue;
    turns[dive_ends ? 0 : 1].push_back(rad_to_deg(turn));
    kinematic[dive_ends ? 0 : 1].push_back(rad_to_deg(pitch_over));
  }
  for (int j = 0; j < 2; ++j) {
    m.inflection_turn_deg[j] = median(turns[j]);
    m.inflection_kinematic_deg[j] = median(kinematic[j]);
  }
}

}  // namespace

HeadingMetrics heading_metrics(const flightlog::FlightLog& log, double skip_s) {
  const auto& time = log.time();
  const auto& heading = log.column("m_heading");
  const auto& command = log.column("c_heading");
  const auto& state = log.column("m_depth_state");
  const auto* fin = log.find("c_fin");
  HeadingMetrics m;
  double square_sum = 0.0, fin_travel = 0.0, glide_s = 0.0;
  std::vector<double> dive_errors, climb_errors, amplitudes, periods, run_t, run_e;
  double run_state = -1.0, last_t = -1e9, last_fin = std::nan("");
  const double start = log.rows() > 0 ? time[0] : 0.0;
  for (std::size_t i = 0; i < log.rows(); ++i) {
    const bool gliding = state[i] == 1.0 || state[i] == 2.0;
    const bool usable = gliding && time[i] - start >= skip_s && std::isfinite(heading[i]) && std::isfinite(command[i]);
    if (!usable || state[i] != run_state || time[i] - last_t > 10.0) {
      glide_oscillation(run_t, run_e, amplitudes, periods);
      run_t.clear();
      run_e.clear();
      last_fin = std::nan("");
    }
    if (!usable) {
      run_state = -1.0;
      continue;
    }
    const double e = wrap_deg(heading[i] - command[i]);
    ++m.samples;
    square_sum += e * e;
    (state[i] == 1.0 ? dive_errors : climb_errors).push_back(e);
    if (fin != nullptr && std::isfinite((*fin)[i])) {
      if (std::isfinite(last_fin)) {
        fin_travel += std::fabs((*fin)[i] - last_fin);
        glide_s += time[i] - last_t;
      }
      last_fin = (*fin)[i];
    }
    run_t.push_back(time[i]);
    run_e.push_back(e);
    run_state = state[i];
    last_t = time[i];
  }
  glide_oscillation(run_t, run_e, amplitudes, periods);
  inflection_turns(log, skip_s, m);
  if (m.samples == 0) return m;
  m.dive_error_deg = median(dive_errors);
  m.climb_error_deg = median(climb_errors);
  m.rms_error_deg = std::sqrt(square_sum / static_cast<double>(m.samples));
  m.oscillation_amplitude_deg = median(amplitudes);
  m.oscillation_period_s = median(periods);
  m.fin_travel_rad_per_h = glide_s > 0.0 ? 3600.0 * fin_travel / glide_s : std::nan("");
  return m;
}

std::string format(const HeadingMetrics& m) {
  char line[256];
  std::snprintf(line, sizeof(line),
                "median error dive %+6.1f climb %+6.1f deg | oscillation +-%5.1f deg, period %4.0f s | "
                "RMS %5.1f deg | fin travel %5.2f rad/h",
                m.dive_error_deg, m.climb_error_deg, m.oscillation_amplitude_deg, m.oscillation_period_s,
                m.rms_error_deg, m.fin_travel_rad_per_h);
  return line;
}

std::string format_inflections(const HeadingMetrics& m) {
  char line[160];
  std::snprintf(
      line, sizeof(line),
      "inflection turn dive->climb %+5.1f deg (pitch-over %+5.1f), climb->dive %+5.1f deg (pitch-over %+5.1f)",
      m.inflection_turn_deg[0], m.inflection_kinematic_deg[0], m.inflection_turn_deg[1], m.inflection_kinematic_deg[1]);
  return line;
}

}  // namespace glider::heading_study
