// SPDX-License-Identifier: Apache-2.0
#pragma once
// The deployment's health from its segments' measurements: each effect's
// values over time, its shape (constant, line or step: the diagnosis core's
// fit_trend, judged on the segments' scatter) and the alert rule. Cheap
// (no model fit): recomputed at every surfacing from the stored values.
#include <optional>
#include <string>
#include <vector>

#include "glider/diagnose/trend.hpp"
#include "glider/health/measure.hpp"

namespace glider::health {

struct Alert {
  std::string id;  // "<effect>@<since, UTC>": stable while the alert stays raised
  HealthEffect effect = HealthEffect::kDragChange;
  std::string kind;              // "step" or "line"
  double size = 0.0;             // step: the change; line: per day (unit, or a fraction of the level before: relative)
  bool relative = false;         // sized as a fraction of the level before (a step: the effect's rule; a hinge's line)
  double low = 0.0, high = 0.0;  // its 95 % interval
  double since_s = 0.0;          // when it began (deployment time)
  std::string message;           // one line a pilot reads
  std::string check;             // what to check
};

struct EffectAssessment {
  HealthEffect effect = HealthEffect::kDragChange;
  std::vector<std::size_t> segments;  // indices of the segments with a value
  diagnose::Trend trend;              // over the deployment
  // The current level and its 95 % interval (NaN: no value yet).
  double value = 0.0, low = 0.0, high = 0.0;
  // Of that interval, the bias every segment shares (1 sigma; the Reynolds
  // prior's, trend.hpp's SharedBias): it moves the level, never a change
  // between segments, so the "too thin" judgement leaves it out.
  double shared_sigma = 0.0;
  std::optional<double> since_s;  // start of the current level (after a step) or of a line
  bool judged = false;            // enough segments, and the interval resolves the alert threshold
  std::string why;                // not judged: why
  std::vector<Alert> alerts;
};

struct Assessment {
  std::vector<EffectAssessment> effects;  // one per HealthEffect
  std::vector<Alert> alerts;
  std::string state;  // "ok", "alert", "cannot judge"
  std::size_t judged_segments = 0;
};

struct AssessOptions {
  std::size_t min_segments = 3;   // for a shape (and any alert)
  double line_window_days = 2.0;  // a line (fouling) is judged on the segments of the last this many days
  diagnose::TrendOptions trend;
};

// `segments` in time order. `previous`: the alerts raised at the last
// surfacing, whose ids are kept while the same alert stays raised.
Assessment assess(const std::vector<SegmentMeasurement>& segments, const std::vector<Alert>& previous = {},
                  const AssessOptions& options = {});

std::string utc_iso(double unix_seconds);

}  // namespace glider::health
