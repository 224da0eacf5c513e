// SPDX-License-Identifier: Apache-2.0
// Profiles and phases (tools/files/netcdf/trajectory.hpp) on a real log and on
// versions of it made worse: thinned (every 4th and every 8th cycle), with
// holes in the middle of dives, a single dive alone, the surface alone.
// The full log's profiles are checked against the log's own dive record
// (count_glides of the phase segmentation); the others against the full log.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/phases.hpp"
#include "glider/netcdf/trajectory.hpp"

using glider::flightlog::FlightLog;
using glider::netcdf::make_trajectory;
using glider::netcdf::Trajectory;

namespace {

const std::string kLog = GLIDER_SOURCE_DIR "/tests/data/real/comet-2019-222-02-154.csv";

// The rows of `log` for which keep(row) holds.
template <typename Keep>
FlightLog subset(const FlightLog& log, Keep keep) {
  std::vector<glider::flightlog::Column> columns(log.column_names().size());
  std::size_t time_index = 0;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const auto& source = log.column(log.column_names()[c]);
    if (&source == &log.time()) time_index = c;
    for (std::size_t r = 0; r < log.rows(); ++r) {
      if (keep(r)) columns[c].push_back(source[r]);
    }
  }
  return FlightLog(log.source(), log.metadata(), log.column_names(), columns, time_index);
}

// Rows of profile `number`, first and last.
std::pair<std::size_t, std::size_t> rows_of(const Trajectory& t, int number) {
  const auto first = std::find(t.profile.begin(), t.profile.end(), number) - t.profile.begin();
  const auto last = t.profile.rend() - std::find(t.profile.rbegin(), t.profile.rend(), number) - 1;
  return {static_cast<std::size_t>(first), static_cast<std::size_t>(last)};
}

}  // namespace

TEST_GROUP(NetcdfProfiles) { FlightLog log = glider::flightlog::read_flight_log(kLog); };

TEST(NetcdfProfiles, FullLogHasOneProfilePerDiveAndClimb) {
  const Trajectory t = make_trajectory(log);
  const auto segments = glider::flightlog::find_segments(t.time_s, t.depth_m, t.phase);
  const auto glides = glider::flightlog::count_glides(segments);
  CHECK(glides.dives > 10);
  LONGS_EQUAL(glides.dives + glides.climbs, t.profiles);
  // Numbered 1..N in time order, each a run of consecutive rows.
  int previous = 0;
  for (const int p : t.profile) {
    if (p == 0) continue;
    CHECK(p == previous || p == previous + 1);
    previous = p;
  }
  LONGS_EQUAL(t.profiles, static_cast<std::size_t>(previous));
}

TEST(NetcdfProfiles, ThinnedLogsKeepEveryProfile) {
  const std::size_t full = make_trajectory(log).profiles;
  for (const std::size_t step : {4U, 8U}) {
    const Trajectory t = make_trajectory(subset(log, [&](std::size_t r) { return r % step == 0; }));
    LONGS_EQUAL(full, t.profiles);
  }
}

TEST(NetcdfProfiles, HolesInsideDivesDoNotSplitThem) {
  const Trajectory reference = make_trajectory(log);
  // Cut 90 s out of the middle of every third profile.
  std::vector<bool> keep(log.rows(), true);
  for (int p = 1; p <= static_cast<int>(reference.profiles); p += 3) {
    const auto [first, last] = rows_of(reference, p);
    const double mid = 0.5 * (reference.time_s[first] + reference.time_s[last]);
    for (std::size_t r = first; r <= last; ++r) keep[r] = std::abs(reference.time_s[r] - mid) > 45.0;
  }
  const Trajectory t = make_trajectory(subset(log, [&](std::size_t r) { return keep[r]; }));
  LONGS_EQUAL(reference.profiles, t.profiles);
}

TEST(NetcdfProfiles, SingleDiveAloneIsOneProfile) {
  const Trajectory reference = make_trajectory(log);
  int dive = 0;
  for (int p = 1; p <= static_cast<int>(reference.profiles) && dive == 0; ++p) {
    if (reference.phase[rows_of(reference, p).first] == glider::flightlog::Phase::kDive) dive = p;
  }
  CHECK(dive > 0);
  const auto [first, last] = rows_of(reference, dive);
  const Trajectory t = make_trajectory(subset(log, [&](std::size_t r) { return r >= first && r <= last; }));
  LONGS_EQUAL(1, t.profiles);
  CHECK(std::count(t.profile.begin(), t.profile.end(), 1) > static_cast<long>((last - first) * 9 / 10));
}

TEST(NetcdfProfiles, SurfaceAloneHasNoProfile) {
  const Trajectory reference = make_trajectory(log);
  const auto [first, last] = rows_of(reference, 1);
  CHECK(first > 10);
  const Trajectory t = make_trajectory(subset(log, [&, f = first](std::size_t r) { return r < f; }));
  LONGS_EQUAL(0, t.profiles);
}
