// SPDX-License-Identifier: Apache-2.0
#pragma once
// A deployment diagnosed as a whole: many logs (segments) of one glider,
// each diagnosed on its own, then every effect that the segments keep
// finding fitted in every segment, and its values over time explained as a
// constant, a trend or a step (trend.hpp). Gliders foul (drag grows for
// weeks), lose or gain weight, and the pump ages: a pilot wants to see the
// effect as a function of time, not one number per log.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "glider/diagnose/diagnose.hpp"
#include "glider/diagnose/trend.hpp"

namespace glider::diagnose {

struct SegmentInput {
  std::string name;
  // Added to the log's times: logs that all start at 0 (SIL) placed in the
  // deployment. Real logs carry their own (epoch) times: 0.
  double time_offset_s = 0.0;
  std::optional<Observations> observations;  // none: `problem` says why
  std::string problem;
};

struct SegmentResult {
  std::string name;
  double time_s = 0.0;                // middle of the segment's scored samples (with the offset)
  std::optional<Diagnosis> selected;  // the segment's own diagnosis (selection)
  std::optional<Diagnosis> fixed;     // the deployment's effects fitted in this segment
  std::string problem;                // why the segment was not diagnosed (empty: it was)
};

struct EffectHistory {
  Effect effect = Effect::kBuoyancyOffset;
  std::size_t selected_in = 0;                     // segments whose own selection found it
  std::vector<double> value, ci95_low, ci95_high;  // per segment; NaN where it has none
  // Per segment: the value's shift under the Reynolds prior's exponent one
  // sigma higher (Finding::reynolds_prior_shift; 0 where not flown): a bias
  // all segments share, carried into the trend's levels (trend.hpp).
  std::vector<double> reynolds_prior_shift;
  Trend trend;
};

struct DeploymentDiagnosis {
  std::vector<SegmentResult> segments;
  std::vector<EffectHistory> effects;  // the deployment's effects, in the order found
  std::size_t diagnosed = 0;           // segments with a diagnosis
};

struct DeploymentOptions {
  DiagnoseOptions diagnose;  // how each segment is diagnosed
  // An effect is the deployment's when the segments' own selections find it
  // in at least this many segments and this fraction of them.
  std::size_t min_segments = 2;
  double min_fraction = 0.2;
  // Fit exactly these in every segment (no selection pass). Empty: select.
  std::vector<Effect> effects;
  TrendOptions trend;
  // Called before each segment's diagnosis: (pass 1 selection / 2 fit, index, name).
  std::function<void(int pass, std::size_t index, const std::string& name)> progress;
};

DeploymentDiagnosis diagnose_deployment(const model::VehicleParams& nominal, const std::vector<SegmentInput>& segments,
                                        const DeploymentOptions& options = {});

}  // namespace glider::diagnose
