// SPDX-License-Identifier: Apache-2.0
#include "glider/health/assess.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

namespace glider::health {
namespace {

constexpr double kDay = 86400.0;

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// The level after the last segment's time and its interval, from the shape.
void current_level(EffectAssessment& a, const std::vector<double>& t, const std::vector<double>& v,
                   const std::vector<SegmentMeasurement>& segments) {
  const diagnose::Trend& tr = a.trend;
  const std::size_t n = v.size();
  switch (tr.shape) {
    case diagnose::TrendShape::kConstant:
      a.value = tr.mean.value;
      a.low = tr.mean.low;
      a.high = tr.mean.high;
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
      a.since_s = tr.first_time_s;
      return;
    }
    case diagnose::TrendShape::kStep: {
      // step_after_s went through days and back: a second's tolerance.
      std::vector<double> after;
      for (std::size_t i = 0; i < n; ++i) {
        if (t[i] >= tr.step_after_s - 1.0) after.push_back(v[i]);
      }
      if (after.size() < 2) after.assign(v.end() - 2, v.end());  // min_step_side is at least 2
      const diagnose::Interval i = diagnose::mean_with_interval(after);
      a.value = i.value;
      a.low = i.low;
      a.high = i.high;
      for (std::size_t k : a.segments) {
        if (segments[k].time_s >= tr.step_after_s - 1.0) {
          a.since_s = segments[k].start_s;
          break;
        }
      }
      return;
    }
    case diagnose::TrendShape::kNone: {
      const EffectValue& last = segments[a.segments.back()].effects[static_cast<std::size_t>(a.effect)];
      a.value = last.value;
      a.low = last.low;
      a.high = last.high;
      return;
    }
  }
}

std::string step_message(const HealthEffectInfo& e, double change, double low, double high, double before,
                         bool relative) {
  std::string text = std::string(e.id) + " changed by " + number(change) + " " + e.unit + " [" + number(low) + ", " +
                     number(high) + "]";
  if (relative && before != 0.0) text += " (" + number(100.0 * change / std::abs(before)) + " %)";
  return text + " in one step, from " + number(before) + " " + e.unit;
}

}  // namespace

std::string utc_iso(double unix_seconds) {
  const std::time_t t = static_cast<std::time_t>(std::floor(unix_seconds));
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

Assessment assess(const std::vector<SegmentMeasurement>& segments, const std::vector<Alert>& previous,
                  const AssessOptions& options) {
  Assessment result;
  for (const SegmentMeasurement& s : segments) result.judged_segments += s.judged ? 1 : 0;
  for (std::size_t index = 0; index < kHealthEffectCount; ++index) {
    EffectAssessment& a = result.effects.emplace_back();
    a.effect = health_effect(index);
    const HealthEffectInfo& e = info(a.effect);
    std::vector<double> t, v;
    std::string last_why;
    for (std::size_t k = 0; k < segments.size(); ++k) {
      const EffectValue& value = segments[k].effects[index];
      if (value.judged()) {
        a.segments.push_back(k);
        t.push_back(segments[k].time_s);
        v.push_back(value.value);
      } else if (!value.why.empty()) {
        last_why = segments[k].name + ": " + value.why;
      }
    }
    if (v.empty()) {
      a.value = a.low = a.high = std::nan("");
      a.why = last_why.empty() ? "no segment" : last_why;
      continue;
    }
    a.trend = diagnose::fit_trend(t, v, options.trend);
    current_level(a, t, v, segments);
    if (v.size() < options.min_segments) {
      a.why = "only " + std::to_string(v.size()) + " segment(s) with a value (" + std::to_string(options.min_segments) +
              " needed for a shape)" + (last_why.empty() ? "" : "; last not judged: " + last_why);
      continue;
    }
    // Too thin to judge: the interval of the level is wider than the change
    // the alert rule is about.
    const double scale = e.rule.relative ? std::abs(a.value) : 1.0;
    const double threshold = e.rule.step_size * scale;
    if (!(std::isfinite(a.low) && std::isfinite(a.high))) {
      a.judged = true;  // one number per segment: the scatter about the shape judges it
    } else if (threshold > 0.0 && 0.5 * (a.high - a.low) > threshold) {
      a.why = "the data are too thin: the 95 % interval of the level (+-" + number(0.5 * (a.high - a.low)) + " " +
              e.unit + ") is wider than the change that matters (" + number(threshold) + " " + e.unit + ")";
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
        alert.low = tr.step_change.low * per;
        alert.high = tr.step_change.high * per;
        alert.relative = e.rule.relative;
        alert.since_s = a.since_s.value_or(tr.step_after_s);
        alert.message =
            step_message(e, size, tr.step_change.low, tr.step_change.high, tr.level_before, e.rule.relative) +
            " (p = " + number(tr.p_step) + ")";
        alert.check = e.check;
        a.alerts.push_back(alert);
      }
    }
    // A line over the recent days (fouling grows for weeks from some day on:
    // the deployment's line would average the days before it in).
    if (e.rule.rate_per_day > 0.0) {
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
