// SPDX-License-Identifier: Apache-2.0
#include "glider/flightlog/gaps.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace glider::flightlog {
namespace {

constexpr double kEmpty = std::numeric_limits<double>::quiet_NaN();

void check_lengths(std::span<const double> time, std::span<const double> values, const char* function) {
  if (time.size() != values.size()) {
    throw std::invalid_argument(std::string(function) + ": " + std::to_string(values.size()) + " values for " +
                                std::to_string(time.size()) + " times");
  }
}

std::vector<std::size_t> valid_indices(std::span<const double> values) {
  std::vector<std::size_t> valid;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isnan(values[i])) valid.push_back(i);
  }
  return valid;
}

}  // namespace

Column forward_fill(std::span<const double> time, std::span<const double> values, double max_age_s) {
  check_lengths(time, values, "forward_fill");
  Column out(values.begin(), values.end());
  double held = kEmpty;
  double held_time = 0.0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (!std::isnan(out[i])) {
      held = out[i];
      held_time = time[i];
    } else if (time[i] - held_time <= max_age_s) {
      out[i] = held;  // still NaN before the first valid value
    }
  }
  return out;
}

namespace {

// Fills each short gap between two valid samples a and b with
// between(value_a, value_b, fraction of the way in time); one rule for both fills.
template <typename Between>
Column fill_short_gaps(std::span<const double> time, std::span<const double> values, double max_gap_s, const char* what,
                       Between between) {
  check_lengths(time, values, what);
  Column out(values.begin(), values.end());
  const std::vector<std::size_t> valid = valid_indices(values);
  for (std::size_t k = 0; k + 1 < valid.size(); ++k) {
    const std::size_t a = valid[k];
    const std::size_t b = valid[k + 1];
    const double span_s = time[b] - time[a];
    if (b == a + 1 || span_s > max_gap_s) continue;
    for (std::size_t i = a + 1; i < b; ++i) out[i] = between(values[a], values[b], (time[i] - time[a]) / span_s);
  }
  return out;
}

}  // namespace

Column interpolate_linear(std::span<const double> time, std::span<const double> values, double max_gap_s) {
  return fill_short_gaps(time, values, max_gap_s, "interpolate_linear",
                         [](double a, double b, double w) { return std::lerp(a, b, w); });
}

Column interpolate_angle_rad(std::span<const double> time, std::span<const double> values, double max_gap_s) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  return fill_short_gaps(time, values, max_gap_s, "interpolate_angle_rad", [](double a, double b, double w) {
    const double turn = std::remainder(b - a, kTwoPi);  // the shorter arc, [-pi, pi]
    const double angle = std::fmod(a + turn * w, kTwoPi);
    return angle < 0.0 ? angle + kTwoPi : angle;
  });
}

Column derive_depth_rate(std::span<const double> time, std::span<const double> depth, double max_gap_s) {
  check_lengths(time, depth, "derive_depth_rate");
  Column out(depth.size(), kEmpty);
  const std::vector<std::size_t> valid = valid_indices(depth);
  for (std::size_t k = 0; k < valid.size(); ++k) {
    const std::size_t i = valid[k];
    // The neighbours that are close enough in time, else i itself.
    std::size_t first = i;
    std::size_t last = i;
    if (k > 0 && time[i] - time[valid[k - 1]] <= max_gap_s) first = valid[k - 1];
    if (k + 1 < valid.size() && time[valid[k + 1]] - time[i] <= max_gap_s) last = valid[k + 1];
    if (first != last) out[i] = (depth[last] - depth[first]) / (time[last] - time[first]);
  }
  return out;
}

}  // namespace glider::flightlog
