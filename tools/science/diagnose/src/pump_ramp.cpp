// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/pump_ramp.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "glider/model/first_order_lag.hpp"

namespace glider::diagnose {
namespace {

constexpr double kJitterCc = 1.0;  // a move smaller than this is the sensor's, not the pump's

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto middle = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

int direction(double v0, double v1) {
  const double d = v1 - v0;
  return std::abs(d) <= kJitterCc ? 0 : (d > 0.0 ? 1 : -1);
}

struct Stroke {
  std::size_t first, last;  // intervals [first, first + 1] .. [last, last + 1]
  int sign;
};

}  // namespace

std::vector<PumpRamp> pump_ramps(std::span<const double> time_s, std::span<const double> ballast_cc,
                                 std::span<const std::size_t> run_first) {
  const std::size_t n = time_s.size();
  std::vector<PumpRamp> ramps(n);
  std::vector<Stroke> strokes;
  for (std::size_t run = 0; run < run_first.size(); ++run) {
    const std::size_t end = run + 1 < run_first.size() ? run_first[run + 1] : n;
    for (std::size_t i = run_first[run]; i + 1 < end; ++i) {
      const int sign = direction(ballast_cc[i], ballast_cc[i + 1]);
      if (sign == 0) continue;
      if (!strokes.empty() && strokes.back().last + 1 == i && strokes.back().sign == sign) {
        strokes.back().last = i;
      } else {
        strokes.push_back({i, i, sign});
      }
    }
  }
  auto rate = [&](std::size_t i) { return std::abs(ballast_cc[i + 1] - ballast_cc[i]) / (time_s[i + 1] - time_s[i]); };
  std::array<std::vector<double>, 2> inner_rates;  // emptying, filling
  for (const Stroke& s : strokes) {
    for (std::size_t i = s.first + 1; i < s.last; ++i) inner_rates[s.sign > 0 ? 1 : 0].push_back(rate(i));
  }
  const std::array<double, 2> log_rate{median(inner_rates[0]), median(inner_rates[1])};
  for (const Stroke& s : strokes) {
    std::vector<double> own;
    for (std::size_t i = s.first + 1; i < s.last; ++i) own.push_back(rate(i));
    const double r = own.empty() ? log_rate[s.sign > 0 ? 1 : 0] : median(own);
    if (!(r > 0.0) || !std::isfinite(r)) continue;  // rate unknown: straight lines
    // The fraction of interval i the pump needs at rate r for its move.
    auto needed = [&](std::size_t i) { return std::min(1.0, rate(i) / r); };
    if (s.first == s.last) {
      const double half = 0.5 * needed(s.first);
      ramps[s.first] = {0.5 - half, 0.5 + half};
      continue;
    }
    ramps[s.first] = {1.0 - needed(s.first), 1.0};
    ramps[s.last] = {0.0, needed(s.last)};
  }
  return ramps;
}

double ramp_value(double v0, double v1, const PumpRamp& ramp, double f) {
  if (f <= ramp.start) return v0;
  if (f >= ramp.end) return v1;
  return v0 + (v1 - v0) * (f - ramp.start) / (ramp.end - ramp.start);
}

double lag_over_ramp(double y0, double v0, double v1, const PumpRamp& ramp, double f0, double f, double dt_s,
                     double tau_s) {
  if (!(tau_s > 0.0)) return ramp_value(v0, v1, ramp, f);
  // The input is a straight line between the breakpoints: exact piece by piece.
  double y = y0, from = f0;
  for (const double corner : {ramp.start, ramp.end}) {
    if (corner <= from || corner >= f) continue;
    y = model::first_order_lag_after(y, ramp_value(v0, v1, ramp, from), ramp_value(v0, v1, ramp, corner),
                                     (corner - from) * dt_s, tau_s);
    from = corner;
  }
  return model::first_order_lag_after(y, ramp_value(v0, v1, ramp, from), ramp_value(v0, v1, ramp, f), (f - from) * dt_s,
                                      tau_s);
}

}  // namespace glider::diagnose
