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
  std::vector<double> shift;     // the shared bias's shift at each point (0: none)
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

// A hinge at `hinge_day`: y = level + slope max(0, t - hinge_day), least
// squares; `parameters` counted in the residual's degrees of freedom.
struct HingeFit {
  double rss = std::numeric_limits<double>::infinity();
  double level = 0.0, slope = 0.0, se_level = 0.0, se_slope = 0.0, end = 0.0, se_end = 0.0, dof = 0.0;
};

HingeFit hinge_at(const Points& p, double hinge_day, std::size_t parameters) {
  const std::size_t n = p.size();
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::max(0.0, p.t_day[i] - hinge_day);
  const double x_mean = mean_of(x, 0, n), y_mean = mean_of(p.y, 0, n);
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - x_mean) * (x[i] - x_mean);
    sxy += (x[i] - x_mean) * (p.y[i] - y_mean);
  }
  HingeFit f;
  if (sxx <= 0.0 || n <= parameters) return f;  // the segments after it at one time
  f.slope = sxy / sxx;
  f.level = y_mean - f.slope * x_mean;
  f.rss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = p.y[i] - (f.level + f.slope * x[i]);
    f.rss += r * r;
  }
  f.dof = static_cast<double>(n - parameters);
  const double s2 = f.rss / f.dof, x_end = x[n - 1];
  f.se_slope = std::sqrt(s2 / sxx);
  f.se_level = std::sqrt(s2 * (1.0 / static_cast<double>(n) + x_mean * x_mean / sxx));
  f.end = f.level + f.slope * x_end;
  f.se_end = std::sqrt(s2 * (1.0 / static_cast<double>(n) + (x_end - x_mean) * (x_end - x_mean) / sxx));
  return f;
}

// Constant up to a segment, then a line (fouling from some day on): the
// hinge searched at each segment that leaves `min_step_side` segments (three
// at least) on the line after it and at least two before (one before is the
// line), its slope
// tested like the line's and corrected for the places searched like the
// step's. The onset then is refined between the neighbouring segments (it
// rarely falls on a segment's time, and a hinge put at the wrong segment
// biases the rate): the estimates and intervals are that fit's, the onset
// counted as a parameter.
void fit_hinge(const Points& p, const TrendOptions& options, Trend& trend, double scale) {
  // A line is judged on three segments at least (two always fit one).
  const std::size_t n = p.size(), side = std::max<std::size_t>(3, options.min_step_side);
  trend.bic_hinge = std::numeric_limits<double>::infinity();
  if (n < side + 3) return;
  std::size_t places = 0, best_k = 0;
  HingeFit best;
  for (std::size_t k = 1; k + side < n; ++k) {
    ++places;
    const HingeFit f = hinge_at(p, p.t_day[k], 2);
    if (f.rss < best.rss) {
      best = f;
      best_k = k;
    }
  }
  if (!std::isfinite(best.rss)) return;
  trend.p_hinge = std::min(1.0, static_cast<double>(places) * two_sided_p(best.slope / best.se_slope, best.dof));
  trend.bic_hinge = bic(best.rss, n, 3, scale);
  constexpr int kSteps = 16;  // per interval between segments
  const double from = p.t_day[best_k - 1], to = p.t_day[best_k + 1];
  double hinge_day = p.t_day[best_k];
  HingeFit refined = hinge_at(p, hinge_day, 3);
  for (int j = 0; j <= 2 * kSteps; ++j) {
    const double day = from + (to - from) * j / (2.0 * kSteps);
    const HingeFit f = hinge_at(p, day, 3);
    if (f.rss < refined.rss) {
      refined = f;
      hinge_day = day;
    }
  }
  trend.hinge_s = p.first_time_s + hinge_day * kSecondsPerDay;
  trend.hinge_slope_per_day = fitting_core::t_interval(refined.slope, refined.se_slope, refined.dof);
  trend.hinge_level = fitting_core::t_interval(refined.level, refined.se_level, refined.dof);
  trend.hinge_end = fitting_core::t_interval(refined.end, refined.se_end, refined.dof);
}

// The level's interval widened by the bias every segment shares: the
// level's shift (the same estimator on the shifts) in quadrature with the
// scatter's half-width.
void add_shared(Interval& level, SharedBias& shared, double level_shift) {
  shared.between_half_width = 0.5 * (level.high - level.low);
  shared.sigma = std::abs(level_shift);
  const double half = std::hypot(shared.between_half_width, fitting_core::kZ95 * shared.sigma);
  level.low = level.value - half;
  level.high = level.value + half;
}

// The shared shifts through each level's estimator: the mean, the line's
// start, the hinge's level and its end (the hinge at the values' onset).
void add_shared_bias(const Points& p, Trend& trend) {
  bool any = false;
  for (double x : p.shift) any = any || x != 0.0;
  if (!any) return;
  Points shifts = p;
  shifts.y = p.shift;
  add_shared(trend.mean, trend.mean_shared, mean_of(shifts.y, 0, shifts.size()));
  if (std::isfinite(trend.bic_linear)) {
    Trend moved;
    fit_linear(shifts, moved, 1.0);
    add_shared(trend.at_start, trend.at_start_shared, moved.at_start.value);
  }
  if (std::isfinite(trend.bic_hinge)) {
    const HingeFit moved = hinge_at(shifts, (trend.hinge_s - p.first_time_s) / kSecondsPerDay, 3);
    if (std::isfinite(moved.rss)) {
      add_shared(trend.hinge_level, trend.hinge_level_shared, moved.level);
      add_shared(trend.hinge_end, trend.hinge_end_shared, moved.end);
    }
  }
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", x);
  return text;
}

std::string bracket(const Interval& i) {
  std::string text("[");  // by append: GCC 12's false -Wrestrict on "literal" + std::string&&
  return text.append(number(i.low)).append(", ").append(number(i.high)).append("]");
}

// The shared bias named where it widened a level.
std::string shared_text(const SharedBias& shared, const std::string& unit) {
  if (shared.sigma == 0.0) return "";
  return " (with a bias all segments share, sigma " + number(shared.sigma) + unit + ")";
}

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
    case TrendShape::kHinge:
      return "hinge";
  }
  return "none";
}

Trend fit_trend(std::span<const double> time_s, std::span<const double> value, const TrendOptions& options,
                std::span<const double> shared_shift) {
  Trend trend;
  Points p;
  bool first = true;
  for (std::size_t i = 0; i < std::min(time_s.size(), value.size()); ++i) {
    if (!std::isfinite(time_s[i]) || !std::isfinite(value[i])) continue;
    if (first) p.first_time_s = time_s[i];
    first = false;
    p.t_day.push_back((time_s[i] - p.first_time_s) / kSecondsPerDay);
    p.y.push_back(value[i]);
    const double shift = i < shared_shift.size() ? shared_shift[i] : 0.0;
    p.shift.push_back(std::isfinite(shift) ? shift : 0.0);
  }
  trend.segments = p.size();
  trend.first_time_s = p.first_time_s;
  if (p.size() < 3) return trend;
  double scale = 0.0;
  for (double y : p.y) scale += y * y;
  fit_constant(p, trend, scale);
  fit_linear(p, trend, scale);
  fit_step(p, options, trend, scale);
  fit_hinge(p, options, trend, scale);
  add_shared_bias(p, trend);
  // Three shapes are tried on every series: each at a third of the level
  // keeps the chance of a spurious line, step or hinge in constant data at
  // the level. Among the significant ones, the lowest BIC.
  const double level = options.significance / 3.0;
  trend.shape = TrendShape::kConstant;
  double best = trend.bic_constant;
  const auto consider = [&](TrendShape shape, double p_value, double shape_bic) {
    if (p_value < level && shape_bic < best) {
      trend.shape = shape;
      best = shape_bic;
    }
  };
  consider(TrendShape::kLinear, trend.p_slope, trend.bic_linear);
  consider(TrendShape::kStep, trend.p_step, trend.bic_step);
  consider(TrendShape::kHinge, trend.p_hinge, trend.bic_hinge);
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
    case TrendShape::kHinge:
      return hinge_level.value + hinge_slope_per_day.value * std::max(0.0, time_s - hinge_s) / kSecondsPerDay;
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
      return "constant " + number(mean.value) + u + " " + bracket(mean) + shared_text(mean_shared, u) + " over " +
             std::to_string(segments) + " segments (no significant trend or step)";
    case TrendShape::kLinear:
      return "linear: " + number(slope_per_day.value) + u + " per day " + bracket(slope_per_day) + ", from " +
             number(at_start.value) + u + " " + bracket(at_start) + shared_text(at_start_shared, u) +
             " at day 0 (p = " + number(p_slope) + ")";
    case TrendShape::kStep:
      return "step of " + number(step_change.value) + u + " " + bracket(step_change) + " between day " +
             day(step_before_s) + " and day " + day(step_after_s) + " (" + number(level_before) + " -> " +
             number(level_after) + u + ", p = " + number(p_step) + ")";
    case TrendShape::kHinge:
      return "constant " + number(hinge_level.value) + u + " " + bracket(hinge_level) + " to day " + day(hinge_s) +
             ", then " + number(hinge_slope_per_day.value) + u + " per day " + bracket(hinge_slope_per_day) +
             " (p = " + number(p_hinge) + "), " + number(hinge_end.value) + u + " " + bracket(hinge_end) +
             " at the last segment";
  }
  return "";
}

}  // namespace glider::diagnose
