// SPDX-License-Identifier: Apache-2.0
// Dive / climb / inflection / surface segmentation: the rules on made-up
// samples, then the real logs (dive counts checked against their depth
// records), the gliderflight CTD log and a SIL log.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/flightlog/columns.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/flightlog/gaps.hpp"
#include "glider/flightlog/phases.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/units.hpp"

using namespace glider::flightlog;

namespace {

constexpr double E = std::numeric_limits<double>::quiet_NaN();
const std::string kRealDir = GLIDER_SOURCE_DIR "/tests/data/real/";

// 30 s at the surface, dive at 0.15 m/s to 30 m, 10 s at depth, climb back,
// 30 s at the surface; 1 Hz.
struct Yo {
  std::vector<double> time;
  std::vector<double> depth;
  Yo() {
    double z = 0.0;
    for (int t = 0; t <= 470; ++t) {
      if (t > 30 && t <= 230) z += 0.15;
      if (t > 240 && t <= 440) z -= 0.15;
      time.push_back(t);
      depth.push_back(std::abs(z) < 1e-9 ? 0.0 : z);
    }
  }
};

std::vector<Phase> phases_of_segments(const std::vector<Segment>& segments) {
  std::vector<Phase> phases;
  for (const Segment& s : segments) phases.push_back(s.phase);
  return phases;
}

}  // namespace

TEST_GROUP(FlightLogPhases){};

TEST(FlightLogPhases, AYoFromDepthAloneIsSurfaceDiveInflectionClimbSurface) {
  const Yo yo;
  const Column rate = derive_depth_rate(yo.time, yo.depth, 30.0);
  const std::vector<Phase> phases = classify_phases(yo.time, yo.depth, rate, {});
  const std::vector<Segment> segments = find_segments(yo.time, yo.depth, phases);
  CHECK_TRUE((std::vector<Phase>{Phase::kSurface, Phase::kDive, Phase::kInflection, Phase::kClimb, Phase::kSurface}) ==
             phases_of_segments(segments));
  DOUBLES_EQUAL(30.0, segments[1].start_s, 0.0);  // the first sample that moves
  DOUBLES_EQUAL(30.0, segments[1].end_depth_m, 1e-9);
  const GlideCounts glides = count_glides(segments);
  LONGS_EQUAL(1, glides.dives);
  LONGS_EQUAL(1, glides.climbs);
  LONGS_EQUAL(0, count_glides(segments, 31.0).dives);
  STRCMP_EQUAL("inflection", std::string(to_string(segments[2].phase)).c_str());
}

TEST(FlightLogPhases, DepthStateDecidesTurnsAndTheSurface) {
  const std::vector<double> t{0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<double> z{0.5, 0.6, 20, 20, 20, 20, 0.3, 0.2};
  const std::vector<double> w{0.12, -0.12, 0.12, -0.12, 0.12, 0.0, 0.12, 0.0};
  const std::vector<double> state{0, 0, 2, 1, 99, 3, 1, E};
  PhaseOptions unbridged;  // sample 5 alone between two dives would join them
  unbridged.bridge_s = 0.0;
  const std::vector<Phase> phases = classify_phases(t, z, w, state, unbridged);
  CHECK_TRUE(Phase::kSurface == phases[0]);  // state 0 near the surface: moving or not
  CHECK_TRUE(Phase::kSurface == phases[1]);
  CHECK_TRUE(Phase::kInflection == phases[2]);  // climb commanded, still sinking
  CHECK_TRUE(Phase::kInflection == phases[3]);  // dive commanded, still rising
  CHECK_TRUE(Phase::kDive == phases[4]);        // 99 (abort) is not a hint: motion decides
  CHECK_TRUE(Phase::kInflection == phases[5]);  // hover: not moving at depth
  CHECK_TRUE(Phase::kDive == phases[6]);        // a dive leaving the surface
  CHECK_TRUE(Phase::kSurface == phases[7]);     // no state: shallow and still
  const std::vector<double> no_depth{E, 1, 1, 1, 1, 1, 1, 1};
  CHECK_TRUE(Phase::kUnknown == classify_phases(t, no_depth, w, {})[0]);
  CHECK_THROWS(std::invalid_argument, classify_phases(t, z, w, std::vector<double>{1.0}));
}

TEST(FlightLogPhases, AShortSlowPatchInsideAGlideIsNotATurn) {
  const std::vector<double> t{0, 4, 8, 12, 16, 20, 24};
  const std::vector<double> z{10, 10.5, 11, 11.1, 11.6, 12.1, 12.6};
  const std::vector<double> w{0.12, 0.12, 0.12, 0.02, 0.12, 0.12, 0.12};
  const std::vector<Phase> phases = classify_phases(t, z, w, {});
  CHECK_TRUE(std::all_of(phases.begin(), phases.end(), [](Phase p) { return p == Phase::kDive; }));
  PhaseOptions strict;
  strict.bridge_s = 0.0;
  CHECK_TRUE(Phase::kInflection == classify_phases(t, z, w, {}, strict)[3]);
}

TEST(FlightLogPhases, RealLogsHaveTheirYos) {
  struct Expected {
    const char* file;
    std::size_t glides;  // dives and climbs each (every yo is complete)
  };
  // comet-2016: 18 full yos to ~41 m, plus a 0.3 m bob at the end that is
  // not counted; the others as their README and depth records show.
  for (const Expected& e :
       {Expected{"comet-2016-174-05.csv", 18}, Expected{"gpl-3.0-or-later/amadeus-2014-204-05-000.csv", 6},
        Expected{"comet-2019-222-02-154.csv", 17}, Expected{"comet-2019-222-02-156.csv", 20}}) {
    const FlightLog log = read_flight_log(kRealDir + e.file);
    const std::vector<Phase> phases = classify_phases(log);
    const std::vector<Segment> segments = find_segments(log.time(), log.column("m_depth"), phases);
    const GlideCounts glides = count_glides(segments);
    LONGS_EQUAL(e.glides, glides.dives);
    LONGS_EQUAL(e.glides, glides.climbs);
    LONGS_EQUAL(0, std::count(phases.begin(), phases.end(), Phase::kUnknown));
    // Every counted glide spans most of the water column (yos of 35-45 m).
    for (const Segment& s : segments) {
      if ((s.phase == Phase::kDive || s.phase == Phase::kClimb) && std::abs(s.end_depth_m - s.start_depth_m) >= 3.0) {
        CHECK(std::abs(s.end_depth_m - s.start_depth_m) > 25.0);
      }
    }
    // The glider's own state agrees on nearly every glide sample.
    const Column& state = log.column("m_depth_state");
    std::size_t gliding = 0;
    std::size_t agreeing = 0;
    for (std::size_t i = 0; i < phases.size(); ++i) {
      if (phases[i] != Phase::kDive && phases[i] != Phase::kClimb) continue;
      ++gliding;
      agreeing += (phases[i] == Phase::kDive ? 1.0 : 2.0) == state[i] ? 1 : 0;
    }
    CHECK(agreeing > gliding * 9 / 10);
  }
}

TEST(FlightLogPhases, CtdOnlyLogSegmentsFromPressure) {
  // gliderflight-adcp: pressure at ~1 Hz, no state, no depth rate. Its DVL
  // speed exists only on dives below 12 dbar: those samples must be dives.
  ReadOptions options;
  options.time_column = "time";
  options.required = {{"pressure_bar"}, {"u_adcp_m_s"}};
  const FlightLog log = read_flight_log(kRealDir + "gliderflight-adcp.csv", options);
  Column depth = log.column("pressure_bar");
  for (double& d : depth) d = glider::bar_to_approx_depth_m(d);
  const Column rate = derive_depth_rate(log.time(), depth, 30.0);
  const std::vector<Phase> phases = classify_phases(log.time(), depth, rate, {});
  const GlideCounts glides = count_glides(find_segments(log.time(), depth, phases));
  LONGS_EQUAL(18, glides.dives);  // the same 18 yos as comet-2016-174-05.csv
  LONGS_EQUAL(18, glides.climbs);
  const Column& u = log.column("u_adcp_m_s");
  std::size_t with_speed = 0;
  std::size_t in_dives = 0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (std::isnan(u[i])) continue;
    ++with_speed;
    in_dives += phases[i] == Phase::kDive ? 1 : 0;
  }
  LONGS_EQUAL(4034, with_speed);
  CHECK(in_dives > with_speed * 95 / 100);
}

TEST(FlightLogPhases, ReadsTheSilDemoLog) {
  // The SIL's own log, end to end: written by the SIL, read like a real one.
  using namespace glider;
  const auto vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  const auto config =
      fw::read_flight_config(config::TomlDocument::load(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"));
  sil::ScenarioOptions options;
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/flightlog_demo.csv";
  const sil::ScenarioResult result = sil::run_scenario(vehicle, config, options);
  STRCMP_EQUAL("", result.error.c_str());
  const FlightLog log = read_flight_log(options.log_path);
  LONGS_EQUAL(result.log_rows, log.rows());
  STRCMP_EQUAL("slocum_we01", log.vehicle_metadata().at(0).value.c_str());
  const std::vector<Phase> phases = classify_phases(log);
  const GlideCounts glides = count_glides(find_segments(log.time(), log.column("m_depth"), phases));
  LONGS_EQUAL(3, glides.dives);  // 3 yos between 5 m and 50 m, then the surfacing
  LONGS_EQUAL(3, glides.climbs);
}
