// SPDX-License-Identifier: Apache-2.0
// Gap handling of sparse log columns: forward fill with a maximum age, linear
// interpolation with a maximum gap, depth rate from depth; depth from the CTD.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "glider/flightlog/columns.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/gaps.hpp"

using namespace glider::flightlog;

namespace {

constexpr double E = std::numeric_limits<double>::quiet_NaN();  // an empty sample
const std::string kRealDir = GLIDER_SOURCE_DIR "/tests/data/real/";

void check_column(const std::vector<double>& expected, const Column& actual) {
  LONGS_EQUAL(expected.size(), actual.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (std::isnan(expected[i])) {
      CHECK_TRUE(std::isnan(actual[i]));
    } else {
      DOUBLES_EQUAL(expected[i], actual[i], 1e-12);
    }
  }
}

double median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
  return values[values.size() / 2];
}

}  // namespace

TEST_GROUP(FlightLogGaps){};

TEST(FlightLogGaps, ForwardFillCarriesOnlyValuesYoungerThanMaxAge) {
  const std::vector<double> t{0, 1, 2, 3, 4, 10, 11, 12, 250};
  const std::vector<double> v{E, 5, E, E, E, 7, E, E, E};
  // Before the first value nothing; 5 lasts 2 s; 7 lasts through 12 s but not
  // over the 238 s surface gap.
  check_column({E, 5, 5, 5, E, 7, 7, 7, E}, forward_fill(t, v, 2.0));
  check_column({E, 5, 5, 5, 5, 7, 7, 7, 7}, forward_fill(t, v, std::numeric_limits<double>::infinity()));
  check_column(v, forward_fill(t, v, 0.0));  // valid samples are never changed
  CHECK_THROWS(std::invalid_argument, forward_fill(t, std::vector<double>{1, 2}, 1.0));
}

TEST(FlightLogGaps, InterpolationFillsOnlyShortGapsAndNeverExtrapolates) {
  const std::vector<double> t{0, 1, 2, 4, 5, 100, 101};
  const std::vector<double> v{E, 10, E, 16, E, E, 3};
  // 10 -> 16 over 3 s: 12 at t = 2; the gap 4 -> 101 s is too long.
  check_column({E, 10, 12, 16, E, E, 3}, interpolate_linear(t, v, 30.0));
  check_column({E, 10, 12, 16, 16 - 13.0 / 97.0, 16 - 13.0 * 96.0 / 97.0, 3}, interpolate_linear(t, v, 97.0));
  check_column(v, interpolate_linear(t, v, 2.9));
  CHECK_THROWS(std::invalid_argument, interpolate_linear(t, std::vector<double>{}, 1.0));
}

// A heading gap across north is filled near north (a straight line from 6.2
// to 0.1 rad would pass through south, pi); other gaps as the straight line;
// long gaps and the edges stay empty, as interpolate_linear.
TEST(FlightLogGaps, AnglesAreFilledOnTheShorterArc) {
  const double e = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> time{0, 1, 2, 3, 4, 5, 6, 100, 101};
  const std::vector<double> heading{e, 6.2, e, e, 0.1, e, 1.1, e, 2.0};
  const Column out = interpolate_angle_rad(time, heading, 10.0);
  const double turn = 0.1 + 2.0 * M_PI - 6.2;  // 0.183 rad through north
  CHECK(std::isnan(out[0]));
  DOUBLES_EQUAL(std::fmod(6.2 + turn / 3.0, 2.0 * M_PI), out[2], 1e-12);
  DOUBLES_EQUAL(std::fmod(6.2 + 2.0 * turn / 3.0, 2.0 * M_PI), out[3], 1e-12);
  DOUBLES_EQUAL(0.6, out[5], 1e-12);  // an ordinary gap: the straight line
  CHECK(std::isnan(out[7]));          // 95 s apart: left empty
  for (double v : out) CHECK(std::isnan(v) || (v >= 0.0 && v < 2.0 * M_PI));
  // The straight-line fill is what this replaces: it passes near south.
  const Column linear = interpolate_linear(time, heading, 10.0);
  CHECK(std::abs(linear[2] - M_PI) < 1.2);
}

TEST(FlightLogGaps, DepthRateIsCentredOneSidedAtEdgesAndEmptyAcrossGaps) {
  const std::vector<double> t{0, 1, 2, 3, 4, 100, 200};
  const std::vector<double> z{0, 0.1, 0.3, E, 0.7, 5, 6};
  // Neighbours are the nearest valid samples: t = 2 pairs 1 s with 4 s.
  check_column({0.1, 0.15, 0.2, E, 0.2, E, E}, derive_depth_rate(t, z, 10.0));
  check_column({0.1, 0.15, 0.2, E, 4.7 / 98, 5.3 / 196, 0.01}, derive_depth_rate(t, z, 100.0));
}

TEST(FlightLogGaps, GpsFixesAreNotCarriedDownADive) {
  // m_gps_lat is logged only near the surface (down to ~4.5 m as the dive
  // starts). Forward-filled without a limit it would put a surface fix on
  // every deep sample; with 60 s it stops within ~9 m more of descent.
  const FlightLog log = read_flight_log(kRealDir + "comet-2016-174-05.csv");
  const Column& lat = log.column("m_gps_lat");
  const Column filled = forward_fill(log.time(), lat, 60.0);
  const Column unlimited = forward_fill(log.time(), lat, std::numeric_limits<double>::infinity());
  const Column& depth = log.column("m_depth");
  std::size_t deep = 0;
  std::size_t deep_filled = 0;
  std::size_t deep_unlimited = 0;
  for (std::size_t i = 0; i < depth.size(); ++i) {
    if (depth[i] < 20.0) continue;
    ++deep;
    deep_filled += std::isnan(filled[i]) ? 0 : 1;
    deep_unlimited += std::isnan(unlimited[i]) ? 0 : 1;
  }
  CHECK(deep > 1000);
  LONGS_EQUAL(0, deep_filled);
  LONGS_EQUAL(deep, deep_unlimited);
}

TEST(FlightLogGaps, DerivedDepthRateAgreesWithTheGlidersOwn) {
  for (const char* file :
       {"comet-2016-174-05.csv", "gpl-3.0-or-later/amadeus-2014-204-05-000.csv", "comet-2019-222-02-156.csv"}) {
    const FlightLog log = read_flight_log(kRealDir + file);
    const Column rate = derive_depth_rate(log.time(), log.column("m_depth"), 30.0);
    const Column& logged = log.column("m_depth_rate");
    std::vector<double> differences;
    for (std::size_t i = 0; i < rate.size(); ++i) {
      if (!std::isnan(rate[i]) && !std::isnan(logged[i])) differences.push_back(std::abs(rate[i] - logged[i]));
    }
    CHECK(differences.size() > log.rows() * 9 / 10);
    CHECK(median(differences) < 0.02);  // glides are 0.10-0.20 m/s
  }
}

TEST(FlightLogGaps, DepthFromPressureMatchesMDepth) {
  // 10 m per bar; the real logs' CTD lags m_depth by ~1.4 s, so the median
  // difference over dives and climbs is a few decimetres at most.
  for (const char* file : {"comet-2016-174-05.csv", "gpl-3.0-or-later/amadeus-2014-204-05-000.csv",
                           "comet-2019-222-02-154.csv", "comet-2019-222-02-156.csv"}) {
    ReadOptions options;
    options.columns = {"m_depth", "sci_water_pressure"};
    const FlightLog log = read_flight_log(kRealDir + file, options);
    CHECK_TRUE(depth_series(log)->source == "m_depth");
    const FlightLog ctd_only = read_flight_log(kRealDir + file, {"m_present_time", {}, {"sci_water_pressure"}, {}});
    const auto from_pressure = depth_series(ctd_only);
    STRCMP_EQUAL("sci_water_pressure", from_pressure->source.c_str());
    const Column& depth = log.column("m_depth");
    std::vector<double> differences;
    for (std::size_t i = 0; i < depth.size(); ++i) {
      if (!std::isnan(from_pressure->depth_m[i])) differences.push_back(from_pressure->depth_m[i] - depth[i]);
    }
    CHECK(std::abs(median(differences)) < 0.4);
  }
  CHECK_FALSE(depth_series(parse_flight_log("t,x\n1,2\n", "none.csv", {"t", {}, {}, {}})).has_value());
  STRCMP_EQUAL("bar", std::string(unit_of("sci_water_pressure")).c_str());
  STRCMP_EQUAL("m/s", std::string(unit_of("sim_speed_m_s")).c_str());  // the SIL's part of the schema
  STRCMP_EQUAL("", std::string(unit_of("no_such_column")).c_str());
}
