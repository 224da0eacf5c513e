// SPDX-License-Identifier: Apache-2.0
#include "glider/health/assess.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "glider/utc_time.hpp"

namespace glider::health {
namespace {

constexpr double kDay = 86400.0;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// The start of the first segment with a value after `time_s` (a step's or a
// hinge's: the first that carries the change); times went through days and
// back, hence a second's tolerance.
std::optional<double> first_start_after(double time_s, const EffectAssessment& a,
                                        const std::vector<SegmentMeasurement>& segments) {
  for (std::size_t k : a.segments) {
    if (segments[k].time_s > time_s + 1.0) return segments[k].start_s;
  }
  return std::nullopt;
}

// The level after the last segment's time and its interval, from the shape.
void current_level(EffectAssessment& a, const std::vector<double>& t, const std::vector<double>& v,
                   const std::vector<double>& shift, const std::vector<SegmentMeasurement>& segments) {
  const diagnose::Trend& tr = a.trend;
  const std::size_t n = v.size();
  switch (tr.shape) {
    case diagnose::TrendShape::kConstant:
      a.value = tr.mean.value;
      a.low = tr.mean.low;
      a.high = tr.mean.high;
      a.shared_sigma = tr.mean_shared.sigma;
      return;
    case diagnose::TrendShape::kLinear: {
      // at_start's and the slope's intervals added in quadrature: their
      // covariance is negative, so this is wider than the exact one.
      const double span = (t.back() - tr.first_time_s) / kDay;
      a.value = tr.at(t.back());
      const double h = std::hypot(0.5 * (tr.at_start.high - tr.at_start.low),
                                  span * 0.5 * (tr.slope_per_day.high - tr.slope_per_day.low));
      a.low = a.value - h;
      a.high = a.value + h;
      a.shared_sigma = tr.at_start_shared.sigma;
      a.since_s = tr.first_time_s;
      return;
    }
    case diagnose::TrendShape::kStep: {
      // step_after_s went through days and back: a second's tolerance.
      std::vector<double> after, after_shift;
      for (std::size_t i = 0; i < n; ++i) {
        if (t[i] >= tr.step_after_s - 1.0) {
          after.push_back(v[i]);
          after_shift.push_back(shift[i]);
        }
      }
      if (after.size() < 2) {  // min_step_side is at least 2
        after.assign(v.end() - 2, v.end());
        after_shift.assign(shift.end() - 2, shift.end());
      }
      const diagnose::Interval i = diagnose::mean_with_interval(after);
      // The level's shared bias: the mean of the shifts (common-mode, as the
      // trend's other levels: trend.hpp's SharedBias).
      const double shared = diagnose::mean_with_interval(after_shift).value;
      const double half = std::hypot(0.5 * (i.high - i.low), fitting_core::kZ95 * shared);
      a.value = i.value;
      a.low = i.value - half;
      a.high = i.value + half;
      a.shared_sigma = std::abs(shared);
      a.since_s = first_start_after(tr.step_before_s, a, segments);
      return;
    }
    case diagnose::TrendShape::kHinge:
      a.value = tr.hinge_end.value;
      a.low = tr.hinge_end.low;
      a.high = tr.hinge_end.high;
      a.shared_sigma = tr.hinge_end_shared.sigma;
      a.since_s = first_start_after(tr.hinge_s, a, segments);
      return;
    case diagnose::TrendShape::kNone: {
      const EffectValue& last = segments[a.segments.back()].effects[static_cast<std::size_t>(a.effect)];
      a.value = last.value;
      a.low = last.low;
      a.high = last.high;
      a.shared_sigma = std::abs(last.shared_shift);
      return;
    }
  }
}

// An error every segment shares (the plane's model form: the heading plane
// reads a fin differently at each level) does not average out over
// segments: a level is known no better than its segments' own intervals say.
// The median 95 % half-width of the per-segment intervals on one side of
// `split_s` (before: at or before it); 0 where the segments give none.
double segment_half_width(const EffectAssessment& a, const std::vector<SegmentMeasurement>& segments, double split_s,
                          bool before) {
  std::vector<double> half;
  for (std::size_t k : a.segments) {
    if ((segments[k].time_s <= split_s + 1.0) != before) continue;
    const EffectValue& v = segments[k].effects[static_cast<std::size_t>(a.effect)];
    if (std::isfinite(v.low) && std::isfinite(v.high)) half.push_back(0.5 * (v.high - v.low));
  }
  if (half.empty()) return 0.0;
  std::nth_element(half.begin(), half.begin() + static_cast<std::ptrdiff_t>(half.size() / 2), half.end());
  return half[half.size() / 2];
}

// The 95 % half-width of a ratio a / b from the half-widths of a and b (the
// delta method, a and b independent): the step's and the hinge's relative sizes.
double ratio_half_width(double ratio, double half_a, double half_b, double b) {
  return std::hypot(half_a / std::abs(b), ratio * half_b / std::abs(b));
}

// A step's 95 % interval: the wider of the segments' scatter about the
// levels (the trend's) and their own intervals (an error they share), and
// for a relative rule the change over the level before with the level
// before's own error (the delta method of a ratio).
void step_interval(const EffectAssessment& a, const std::vector<SegmentMeasurement>& segments, bool relative,
                   double& low, double& high) {
  const diagnose::Trend& tr = a.trend;
  const double hb = segment_half_width(a, segments, tr.step_before_s, true);
  const double ha = segment_half_width(a, segments, tr.step_before_s, false);
  const double change = tr.step_change.value;
  const double half = std::max(0.5 * (tr.step_change.high - tr.step_change.low), std::hypot(hb, ha));
  if (!relative) {
    low = change - half;
    high = change + half;
    return;
  }
  const double before = std::abs(tr.level_before);
  const double ratio = change / before;
  const double relative_half = ratio_half_width(ratio, half, hb, before);
  low = ratio - relative_half;
  high = ratio + relative_half;
}

// A hinge's slope 95 % half-width (per day): the wider of the segments'
// scatter about the hinge (the trend's) and their own intervals, as a step's
// (an error every segment shares does not average out): the line's two ends,
// the level at the hinge and the last value, each known no better than the
// median per-segment half-width on its side, over the days between them.
// (The scatter alone gave a drag rate +-1 %, the segments' own intervals
// +-2-9 %.)
double hinge_slope_half_width(const EffectAssessment& a, const std::vector<SegmentMeasurement>& segments,
                              double last_time_s) {
  const diagnose::Trend& tr = a.trend;
  const double scatter = 0.5 * (tr.hinge_slope_per_day.high - tr.hinge_slope_per_day.low);
  const double span_days = (last_time_s - tr.hinge_s) / kDay;
  if (!(span_days > 0.0)) return scatter;
  const double hb = segment_half_width(a, segments, tr.hinge_s, true);
  const double ha = segment_half_width(a, segments, tr.hinge_s, false);
  return std::max(scatter, std::hypot(hb, ha) / span_days);
}

std::string step_message(const HealthEffectInfo& e, double change, double low, double high, double before,
                         bool relative) {
  std::string text = std::string(e.id) + " changed by " + number(change) + " " + e.unit + " [" + number(low) + ", " +
                     number(high) + "]";
  if (relative && before != 0.0) text += " (" + number(100.0 * change / std::abs(before)) + " %)";
  return text + " in one step, from " + number(before) + " " + e.unit;
}

}  // namespace

// The base library's one UTC writer (whole seconds, truncated toward the
// earlier time as the floor before gmtime did; empty for a non-finite time).
std::string utc_iso(double unix_seconds) { return utc::format_iso(std::floor(unix_seconds)); }

Assessment assess(const std::vector<SegmentMeasurement>& segments, const std::vector<Alert>& previous,
                  const AssessOptions& options) {
  Assessment result;
  for (const SegmentMeasurement& s : segments) result.judged_segments += s.judged ? 1 : 0;
  for (std::size_t index = 0; index < kHealthEffectCount; ++index) {
    EffectAssessment& a = result.effects.emplace_back();
    a.effect = health_effect(index);
    const HealthEffectInfo& e = info(a.effect);
    std::vector<double> t, v, shift;
    std::string last_why;
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const EffectValue& value = segments[k].effects[index];
      if (value.judged()) {
        a.segments.push_back(k);
        t.push_back(segments[k].time_s);
        v.push_back(value.value);
        shift.push_back(value.shared_shift);
      } else if (!value.why.empty()) {
        last_why = segments[k].name + ": " + value.why;
      }
    }
    if (v.empty()) {
      a.value = a.low = a.high = std::nan("");
      a.why = last_why.empty() ? "no segment" : last_why;
      continue;
    }
    // The levels carry the bias every segment shares (the diagnosis core's
    // rule, as the deployment view's); the shapes, slopes and steps do not.
    a.trend = diagnose::fit_trend(t, v, options.trend, shift);
    current_level(a, t, v, shift, segments);
    if (v.size() < options.min_segments) {
      a.why = "only " + std::to_string(v.size()) + " segment(s) with a value (" + std::to_string(options.min_segments) +
              " needed for a shape)" + (last_why.empty() ? "" : "; last not judged: " + last_why);
      continue;
    }
    // Too thin to judge: the interval of the level is wider than the change
    // the alert rule is about. A change is a difference between segments:
    // the bias they all share is not in it, so not in this judgement.
    // After a step the change the rule is about is that step, sized against
    // the level before it (the alert's own limit): judged on the step fit's
    // interval of the change (both sides' scatter, n - 2 degrees of freedom:
    // the step test's own). The level after it from the segments after it
    // alone (a Student-t on 1 or 2 degrees of freedom in the surfacings after
    // an onset: 12.7 and 4.3 standard errors) against a quarter of a halved
    // fin held a significant halving "too thin" for a surfacing or two
    // (docs/health.md, "A step judged on the step").
    const bool step = a.trend.shape == diagnose::TrendShape::kStep;
    const double scale = !e.rule.relative ? 1.0 : step ? std::abs(a.trend.level_before) : std::abs(a.value);
    const double threshold = e.rule.step_size * scale;
    const double half = 0.5 * (a.high - a.low), shared_half = fitting_core::kZ95 * a.shared_sigma;
    const double change_half = step ? 0.5 * (a.trend.step_change.high - a.trend.step_change.low)
                                    : std::sqrt(std::max(0.0, half * half - shared_half * shared_half));
    if (!(std::isfinite(a.low) && std::isfinite(a.high))) {
      a.judged = true;  // one number per segment: the scatter about the shape judges it
    } else if (threshold > 0.0 && change_half > threshold) {
      a.why = std::string("the data are too thin: the 95 % interval of the ") + (step ? "step" : "level") + " (+-" +
              number(change_half) + " " + e.unit +
              (shared_half > 0.0 && !step ? " without the bias every segment shares" : "") +
              ") is wider than the change that matters (" + number(threshold) + " " + e.unit + ")";
      continue;
    } else {
      a.judged = true;
    }

    // A step of the deployment.
    const diagnose::Trend& tr = a.trend;
    if (tr.shape == diagnose::TrendShape::kStep) {
      const double size = tr.step_change.value;
      const double limit = e.rule.step_size * (e.rule.relative ? std::abs(tr.level_before) : 1.0);
      if (e.rule.step_size > 0.0 && std::abs(size) >= limit) {
        Alert alert;
        alert.effect = a.effect;
        alert.kind = "step";
        // A relative rule sizes the change as a fraction of the level before:
        // an estimator's scale error (a few %) cancels in the ratio.
        const double per = e.rule.relative ? 1.0 / std::abs(tr.level_before) : 1.0;
        alert.size = size * per;
        step_interval(a, segments, e.rule.relative, alert.low, alert.high);
        alert.relative = e.rule.relative;
        alert.since_s = a.since_s.value_or(tr.step_after_s);
        alert.message = step_message(e, size, alert.low / per, alert.high / per, tr.level_before, e.rule.relative) +
                        " (p = " + number(tr.p_step) + ")";
        alert.check = e.check;
        a.alerts.push_back(alert);
      }
    }
    // A hinge of the deployment (constant, then a line: fouling from some day
    // on), its slope pinned by the whole constant stretch before it.
    // The rate is sized as a fraction of the level before a day (fouling as
    // a fraction of the clean hull's drag): the estimator's scale error (the
    // vertical plane reads the file's drag as 0.99 of it) cancels in the
    // ratio, the level's own error is added (the delta method of a ratio).
    const double hinge_before = std::abs(tr.hinge_level.value);
    const double hinge_rate = hinge_before > 0.0 ? tr.hinge_slope_per_day.value / hinge_before : 0.0;
    const bool hinge_alert = e.rule.rate_per_day > 0.0 && tr.shape == diagnose::TrendShape::kHinge &&
                             std::abs(hinge_rate) >= e.rule.rate_per_day;
    if (hinge_alert) {
      Alert alert;
      alert.effect = a.effect;
      alert.kind = "line";
      alert.size = hinge_rate;
      const double rate_half = ratio_half_width(hinge_rate, hinge_slope_half_width(a, segments, t.back()),
                                                0.5 * (tr.hinge_level.high - tr.hinge_level.low), hinge_before);
      alert.low = hinge_rate - rate_half;
      alert.high = hinge_rate + rate_half;
      alert.relative = true;
      alert.since_s = a.since_s.value_or(tr.hinge_s);
      alert.message = std::string(e.id) + " is changing by " + number(100.0 * alert.size) + " % of its level a day [" +
                      number(100.0 * alert.low) + ", " + number(100.0 * alert.high) + "] since " +
                      utc_iso(alert.since_s) + ", constant at " + number(tr.hinge_level.value) + " " + e.unit +
                      " before (p = " + number(tr.p_hinge) + "), now " + number(tr.hinge_end.value) + " " + e.unit;
      alert.check = e.check;
      a.alerts.push_back(alert);
    }
    // Else a line over the recent days (fouling grows for weeks from some day
    // on: the deployment's line would average the days before it in).
    if (e.rule.rate_per_day > 0.0 && !hinge_alert) {
      std::vector<double> wt, wv, before;
      for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] >= t.back() - options.line_window_days * kDay) {
          wt.push_back(t[i]);
          wv.push_back(v[i]);
        } else {
          before.push_back(v[i]);
        }
      }
      const double span_days = wt.empty() ? 0.0 : (wt.back() - wt.front()) / kDay;
      if (wt.size() >= options.min_segments && span_days >= e.rule.min_line_span_days) {
        const diagnose::Trend w = diagnose::fit_trend(wt, wv, options.trend);
        if (w.p_slope < 0.5 * options.trend.significance && std::abs(w.slope_per_day.value) >= e.rule.rate_per_day) {
          Alert alert;
          alert.effect = a.effect;
          alert.kind = "line";
          alert.size = w.slope_per_day.value;
          alert.low = w.slope_per_day.low;
          alert.high = w.slope_per_day.high;
          // Onset: where the recent line leaves the level before it.
          double onset = wt.front();
          if (before.size() >= 2) {
            const double level = diagnose::mean_with_interval(before).value;
            const double crossing = w.first_time_s + (level - w.at_start.value) / w.slope_per_day.value * kDay;
            onset = std::clamp(crossing, t.front(), wt.front());
          }
          alert.since_s = onset;
          alert.message = std::string(e.id) + " is changing by " + number(alert.size) + " " + e.unit + "/day [" +
                          number(alert.low) + ", " + number(alert.high) + "] over the last " + number(span_days) +
                          " days (p = " + number(w.p_slope) + "), now " + number(wv.back()) + " " + e.unit;
          alert.check = e.check;
          a.alerts.push_back(alert);
        }
      }
    }
    for (Alert& alert : a.alerts) {
      alert.id = std::string(e.id) + "@" + utc_iso(alert.since_s);
      for (const Alert& p : previous) {
        if (p.effect == alert.effect && p.kind == alert.kind) alert.id = p.id;  // the same alert, still raised
      }
      result.alerts.push_back(alert);
    }
  }
  result.state = !result.alerts.empty()                          ? "alert"
                 : result.judged_segments < options.min_segments ? "cannot judge"
                                                                 : "ok";
  return result;
}

}  // namespace glider::health
