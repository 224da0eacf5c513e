// SPDX-License-Identifier: Apache-2.0
#include "glider/diagnose/trend.hpp"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>
#include "glider/fitting_core/intervals.hpp"
#include "glider/fitting_core/selection.hpp"

namespace glider::diagnose {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kSecondsPerDay = 86400.0;

struct Points {
  std::vector<double> t_day, y;  // t relative to the first point
  double first_time_s = 0.0;
  std::size_t size() const { return y.size(); }
};

double two_sided_p(double t, double degrees_of_freedom) {
  if (!std::isfinite(t)) return 0.0;  // a perfect fit: the data leave no doubt
  return 2.0 * boost::math::cdf(boost::math::complement(
                   boost::math::students_t_distribution<double>(degrees_of_freedom), std::abs(t)));
}

// n ln(RSS/n) + k ln n, with the residual sum floored so that data a shape
// fits exactly still compare (and a perfect fit is not -infinity).
double bic(double rss, std::size_t n, std::size_t parameters, double scale) {
  const double floor = 1e-20 * std::max(scale, 1e-300);
  return fitting_core::bic(std::max(rss, floor), static_cast<double>(n), static_cast<double>(parameters));
}

double mean_of(std::span<const double> y, std::size_t from, std::size_t to) {
  double sum = 0.0;
  for (std::size_t i = from; i < to; ++i) sum += y[i];
  return sum / static_cast<double>(to - from);
}

double squares_about(std::span<const double> y, std::size_t from, std::size_t to, double level) {
  double sum = 0.0;
  for (std::size_t i = from; i < to; ++i) sum += (y[i] - level) * (y[i] - level);
  return sum;
}

void fit_constant(const Points& p, Trend& trend, double scale) {
  trend.mean = mean_with_interval(p.y);
  trend.bic_constant = bic(squares_about(p.y, 0, p.size(), trend.mean.value), p.size(), 1, scale);
}

void fit_linear(const Points& p, Trend& trend, double scale) {
  const std::size_t n = p.size();
  const double t_mean = mean_of(p.t_day, 0, n), y_mean = mean_of(p.y, 0, n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (p.t_day[i] - t_mean) * (p.t_day[i] - t_mean);
    sxy += (p.t_day[i] - t_mean) * (p.y[i] - y_mean);
  }
  if (sxx <= 0.0) {  // every segment at one time: no slope to see
    trend.bic_linear = std::numeric_limits<double>::infinity();
    return;
  }
  const double slope = sxy / sxx, start = y_mean - slope * t_mean;
  double rss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = p.y[i] - (start + slope * p.t_day[i]);
    rss += r * r;
  }
  const double dof = static_cast<double>(n - 2);
  const double s2 = rss / dof;
  const double se_slope = std::sqrt(s2 / sxx);
  const double se_start = std::sqrt(s2 * (1.0 / static_cast<double>(n) + t_mean * t_mean / sxx));
  trend.slope_per_day = fitting_core::t_interval(slope, se_slope, dof);
  trend.at_start = fitting_core::t_interval(start, se_start, dof);
  trend.p_slope = two_sided_p(slope / se_slope, dof);
  trend.bic_linear = bic(rss, n, 2, scale);
}

void fit_step(const Points& p, const TrendOptions& options, Trend& trend, double scale) {
  const std::size_t n = p.size(), side = std::max<std::size_t>(1, options.min_step_side);
  if (n < 2 * side || n < 4) {
    trend.bic_step = std::numeric_limits<double>::infinity();
    return;
  }
  std::size_t best_k = 0;
  double best_rss = std::numeric_limits<double>::infinity();
  std::size_t places = 0;
  for (std::size_t k = side; k + side <= n; ++k) {
    ++places;
    const double before = mean_of(p.y, 0, k), after = mean_of(p.y, k, n);
    const double rss = squares_about(p.y, 0, k, before) + squares_about(p.y, k, n, after);
    if (rss < best_rss) {
      best_rss = rss;
      best_k = k;
    }
  }
  const double before = mean_of(p.y, 0, best_k), after = mean_of(p.y, best_k, n);
  const double dof = static_cast<double>(n - 2);
  const double se =
      std::sqrt(best_rss / dof * (1.0 / static_cast<double>(best_k) + 1.0 / static_cast<double>(n - best_k)));
  trend.step_change = fitting_core::t_interval(after - before, se, dof);
  trend.level_before = before;
  trend.level_after = after;
  trend.step_before_s = p.first_time_s + p.t_day[best_k - 1] * kSecondsPerDay;
  trend.step_after_s = p.first_time_s + p.t_day[best_k] * kSecondsPerDay;
  // The step was searched at `places` places: Bonferroni keeps the chance of
  // a spurious step at the significance level.
  trend.p_step = std::min(1.0, static_cast<double>(places) * two_sided_p((after - before) / se, dof));
  trend.bic_step = bic(best_rss, n, 3, scale);
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

std::string bracket(const Interval& i) { return "[" + number(i.low) + ", " + number(i.high) + "]"; }

}  // namespace

const char* to_string(TrendShape shape) {
  switch (shape) {
    case TrendShape::kNone:
      return "none";
    case TrendShape::kConstant:
      return "constant";
    case TrendShape::kLinear:
      return "linear";
    case TrendShape::kStep:
      return "step";
  }
  return "none";
}

Trend fit_trend(std::span<const double> time_s, std::span<const double> value, const TrendOptions& options) {
  Trend trend;
  Points p;
  bool first = true;
  for (std::size_t i = 0; i < std::min(time_s.size(), value.size()); ++i) {
    if (!std::isfinite(time_s[i]) || !std::isfinite(value[i])) continue;
    if (first) p.first_time_s = time_s[i];
    first = false;
    p.t_day.push_back((time_s[i] - p.first_time_s) / kSecondsPerDay);
    p.y.push_back(value[i]);
  }
  trend.segments = p.size();
  trend.first_time_s = p.first_time_s;
  if (p.size() < 3) return trend;
  double scale = 0.0;
  for (double y : p.y) scale += y * y;
  fit_constant(p, trend, scale);
  fit_linear(p, trend, scale);
  fit_step(p, options, trend, scale);
  // Two shapes are tried on every series: each at half the level keeps the
  // chance of a spurious line or step in constant data at the level.
  const double level = 0.5 * options.significance;
  trend.shape = TrendShape::kConstant;
  double best = trend.bic_constant;
  if (trend.p_slope < level && trend.bic_linear < best) {
    trend.shape = TrendShape::kLinear;
    best = trend.bic_linear;
  }
  if (trend.p_step < level && trend.bic_step < best) trend.shape = TrendShape::kStep;
  return trend;
}

double Trend::at(double time_s) const {
  switch (shape) {
    case TrendShape::kNone:
      return kNaN;
    case TrendShape::kConstant:
      return mean.value;
    case TrendShape::kLinear:
      return at_start.value + slope_per_day.value * (time_s - first_time_s) / kSecondsPerDay;
    case TrendShape::kStep:
      return time_s < 0.5 * (step_before_s + step_after_s) ? level_before : level_after;
  }
  return kNaN;
}

std::string Trend::describe(const char* unit) const {
  const std::string u = std::string(" ") + unit;
  const auto day = [&](double t) { return number((t - first_time_s) / kSecondsPerDay); };
  switch (shape) {
    case TrendShape::kNone:
      return "too few segments with a value (" + std::to_string(segments) + ")";
    case TrendShape::kConstant:
      return "constant " + number(mean.value) + u + " " + bracket(mean) + " over " + std::to_string(segments) +
             " segments (no significant trend or step)";
    case TrendShape::kLinear:
      return "linear: " + number(slope_per_day.value) + u + " per day " + bracket(slope_per_day) + ", from " +
             number(at_start.value) + u + " at day 0 (p = " + number(p_slope) + ")";
    case TrendShape::kStep:
      return "step of " + number(step_change.value) + u + " " + bracket(step_change) + " between day " +
             day(step_before_s) + " and day " + day(step_after_s) + " (" + number(level_before) + " -> " +
             number(level_after) + u + ", p = " + number(p_step) + ")";
  }
  return "";
}

}  // namespace glider::diagnose
