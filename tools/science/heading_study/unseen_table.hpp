// SPDX-License-Identifier: Apache-2.0
#pragma once
// The heading replay out of sample (issue 26 item 6): the loop identified on
// one comet-2019 log flown in SIL (heading_replay.hpp) predicting ANOTHER
// log's steady heading error, in either log's water. One row per case, as
// docs/diagnose/heading-replay-unseen.md has them: `glider-heading-study
// --unseen-table` writes that file and sil.HeadingReplayUnseen checks its
// own run against it, so the figures the docs quote cannot drift from what
// the code computes.
#include <optional>
#include <string>
#include <vector>

#include "heading_metrics.hpp"

namespace glider::heading_study {

// Within this of the unseen log's median steady error per glide direction:
// sil.SilHeadingReplay's tolerance on the log the loop was identified on.
constexpr double kSteadyToleranceDeg = 4.0;

struct UnseenCase {
  std::string calibration, unseen;  // file stems in tests/data/real, e.g. comet-2019-222-02-154
  bool unseen_water = false;        // the current's shear identified on the unseen log (else the calibration log's)
};

struct UnseenRow {
  UnseenCase with;
  HeadingMetrics calibration, unseen, predicted;
  bool dive_holds() const;
  bool climb_holds() const;
};

// The four cases of the table: 154 -> 156 and 156 -> 154, each log's water.
std::vector<UnseenCase> unseen_cases();

// Flies one case (`source`: the repository root; the SIL logs go to out_dir).
UnseenRow predict_unseen(const std::string& source, const UnseenCase& with, const std::string& out_dir);

// The table's markdown row of a case ("| 154 | 156's | 156 | +19.9 / -17.5 | ..."): steady errors to 0.1 deg.
std::string table_row(const UnseenRow& row);
// The header lines of the table.
std::string table_header();
// The predicted dive / climb errors a table row states for this case (nullopt: no row for it).
struct StatedPrediction {
  double dive_deg = 0.0, climb_deg = 0.0;
};
std::optional<StatedPrediction> stated_prediction(const std::string& table_text, const UnseenCase& with);

}  // namespace glider::heading_study
