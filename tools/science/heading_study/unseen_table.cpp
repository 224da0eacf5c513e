// SPDX-License-Identifier: Apache-2.0
#include "unseen_table.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "glider/slocum/log_loader.hpp"
#include "heading_replay.hpp"

namespace glider::heading_study {
namespace {

std::string real_log(const std::string& source, const std::string& stem) {
  return source + "/tests/data/real/" + stem + ".csv";
}

// "comet-2019-222-02-154" -> "154": the segment, as the table names the logs.
std::string segment(const std::string& stem) {
  const std::size_t dash = stem.rfind('-');
  return dash == std::string::npos ? stem : stem.substr(dash + 1);
}

std::string row_key(const UnseenCase& c) {
  return "| " + segment(c.calibration) + " | " + segment(c.unseen_water ? c.unseen : c.calibration) + "'s | " +
         segment(c.unseen) + " |";
}

std::string pair(double dive, double climb) {
  char text[48];
  std::snprintf(text, sizeof(text), "%+.1f / %+.1f", dive, climb);
  return text;
}

}  // namespace

bool UnseenRow::dive_holds() const {
  return std::abs(predicted.dive_error_deg - unseen.dive_error_deg) < kSteadyToleranceDeg;
}
bool UnseenRow::climb_holds() const {
  return std::abs(predicted.climb_error_deg - unseen.climb_error_deg) < kSteadyToleranceDeg;
}

std::vector<UnseenCase> unseen_cases() {
  const std::string a = "comet-2019-222-02-154", b = "comet-2019-222-02-156";
  return {{a, b, false}, {a, b, true}, {b, a, false}, {b, a, true}};
}

UnseenRow predict_unseen(const std::string& source, const UnseenCase& with, const std::string& out_dir) {
  ReplayOptions options;
  if (with.unseen_water) options.water_log = real_log(source, with.unseen);
  const Replay r = replay_log(source, real_log(source, with.calibration), source + "/boards/vehicles/slocum_comet.toml",
                              out_dir, options);
  UnseenRow row;
  row.with = with;
  row.calibration = r.real;
  row.predicted = r.sil_identified;
  row.unseen = heading_metrics(slocum::load_flight_log({{real_log(source, with.unseen)}, {}}, {}, nullptr), 0.0);
  return row;
}

std::string table_header() {
  return "Steady heading error per glide direction (deg, median m_heading - c_heading; dive / climb) of the heading "
         "replay out of sample: the loop identified on one comet-2019 log, flown in SIL, against the other log. "
         "Written by `./glider heading-study --unseen-table docs/diagnose/heading-replay-unseen.md`; "
         "sil.HeadingReplayUnseen checks its row against this file.\n\n"
         "| identified on | water flown | predicting | predicted | the log's | within 4 deg (miss dive, climb) |\n"
         "|---|---|---|---|---|---|\n";
}

std::string table_row(const UnseenRow& row) {
  const double dive_miss = std::abs(row.predicted.dive_error_deg - row.unseen.dive_error_deg);
  const double climb_miss = std::abs(row.predicted.climb_error_deg - row.unseen.climb_error_deg);
  const char* verdict = row.dive_holds() && row.climb_holds() ? "yes"
                        : row.dive_holds()                    ? "dive yes, climb no"
                        : row.climb_holds()                   ? "dive no, climb yes"
                                                              : "no";
  char misses[64];
  std::snprintf(misses, sizeof(misses), "%s (%.1f, %.1f)", verdict, dive_miss, climb_miss);
  return row_key(row.with) + " " + pair(row.predicted.dive_error_deg, row.predicted.climb_error_deg) + " | " +
         pair(row.unseen.dive_error_deg, row.unseen.climb_error_deg) + " | " + misses + " |\n";
}

std::optional<StatedPrediction> stated_prediction(const std::string& table_text, const UnseenCase& with) {
  const std::string key = row_key(with);
  std::istringstream lines(table_text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind(key, 0) != 0) continue;
    StatedPrediction p;
    char slash = 0;
    std::istringstream cell(line.substr(key.size()));
    if (cell >> p.dive_deg >> slash >> p.climb_deg && slash == '/') return p;
    return std::nullopt;
  }
  return std::nullopt;
}

}  // namespace glider::heading_study
