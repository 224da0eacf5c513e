// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>

#include "glider/config/toml_document.hpp"
#include "glider/firmware/config/flight_config_file.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/environment_file.hpp"
#include "glider/model/seawater.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/units.hpp"

using namespace glider;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST_GROUP(DemoMission) {
  model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  fw::FlightSoftwareConfig config =
      fw::read_flight_config(config::TomlDocument::load(GLIDER_SOURCE_DIR "/boards/missions/demo_yo.toml"));
  sil::ScenarioOptions options;
};

TEST(DemoMission, CompletesThreeYosBetween5And50m) {
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  STRCMP_EQUAL("", r.error.c_str());
  CHECK_TRUE(r.completed);
  CHECK(r.final_phase == fw::Phase::kSurface);
  CHECK(r.abort_cause == fw::AbortCause::kNone);
  LONGS_EQUAL(3, r.yos);
  const auto& turns = r.stats.inflection_depths_m();
  LONGS_EQUAL(6, turns.size());  // 3 bottoms, 2 tops, and the surfacing
  for (std::size_t i = 0; i + 1 < turns.size(); ++i) {
    if (i % 2 == 0) {
      CHECK(turns[i] >= 49.5 && turns[i] <= 51.0);  // bottom of a dive
    } else {
      CHECK(turns[i] >= 4.0 && turns[i] <= 5.5);  // top of a climb
    }
  }
  CHECK(r.stats.max_depth_m() < 53.0);
  LONGS_EQUAL(0, r.executive.overruns);
}

// The settled glides' pitch: the flight test card tests/cards/demo_glides.toml (./glider regress).

TEST(DemoMission, TwoRunsWriteByteIdenticalLogs) {
  // Water with a CTD, so its noise is in the log too.
  options.environment = model::load_environment_file(GLIDER_SOURCE_DIR "/boards/environments/summer_thermocline.toml");
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/determinism_a.csv";
  const sil::ScenarioResult a = sil::run_scenario(vehicle, config, options);
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/determinism_b.csv";
  const sil::ScenarioResult b = sil::run_scenario(vehicle, config, options);
  STRCMP_EQUAL("", a.error.c_str());
  STRCMP_EQUAL("", b.error.c_str());
  const std::string log_a = slurp(GLIDER_TEST_OUTPUT_DIR "/determinism_a.csv");
  const std::string log_b = slurp(GLIDER_TEST_OUTPUT_DIR "/determinism_b.csv");
  CHECK(log_a.size() > 100000);
  CHECK_TRUE(log_a == log_b);
  CHECK(a.log_rows > 1000);
  // A different seed must change the log (the noise is really there).
  options.seed = 2;
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/determinism_c.csv";
  sil::run_scenario(vehicle, config, options);
  CHECK_FALSE(log_a == slurp(GLIDER_TEST_OUTPUT_DIR "/determinism_c.csv"));
}

TEST(DemoMission, LogFollowsTheFlightLogContract) {
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/contract.csv";
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  std::ifstream in(options.log_path);
  std::string line;
  bool saw_vehicle_name = false;
  while (std::getline(in, line) && line.rfind("# ", 0) == 0) {
    saw_vehicle_name |= line == "# vehicle.name: slocum_we01";
  }
  CHECK_TRUE(saw_vehicle_name);
  STRCMP_EQUAL(sil::CsvFlightLog::header().c_str(), line.c_str());
  double last_time = -1.0;
  std::uint64_t rows = 0;
  std::string last_line;
  while (std::getline(in, line)) {
    last_line = line;
    if (line.rfind("# end: ", 0) == 0) break;
    const double time = std::stod(line.substr(0, line.find(',')));
    CHECK(time > last_time);  // strictly increasing
    last_time = time;
    ++rows;
  }
  LONGS_EQUAL(r.log_rows, rows);  // nothing lost or truncated
  // The trailer is the last line: how the flight ended, rows written and lost.
  STRCMP_EQUAL(("# end: complete rows=" + std::to_string(rows) + " lost=0").c_str(), last_line.c_str());
  CHECK_FALSE(std::getline(in, line));
}

TEST(DemoMission, CtdMeasuresTheWaterTheVehicleFeels) {
  options.environment = model::load_environment_file(GLIDER_SOURCE_DIR "/boards/environments/summer_thermocline.toml");
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/ctd.csv";
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  CHECK_TRUE(r.completed);
  const flightlog::FlightLog log = flightlog::read_flight_log(options.log_path);
  const auto& temp = log.column("sci_water_temp");
  const auto& cond = log.column("sci_water_cond");
  const auto& bar = log.column("sci_water_pressure");
  const auto& state = log.column("m_depth_state");
  const auto& depth = log.column("sim_depth_m");
  const auto& rho = log.column("sim_density_kg_m3");
  std::size_t sampled = 0;
  double worst_rho = 0.0, worst_p = 0.0;
  for (std::size_t i = 0; i < log.rows(); ++i) {
    // Blank at the surface, like the real logs; sampled everywhere else.
    CHECK_EQUAL(state[i] == 0.0, std::isnan(temp[i]));
    if (std::isnan(temp[i])) continue;
    ++sampled;
    // TEOS-10 of the logged T, C, p is the density the vehicle felt; the
    // CTD's noise (2 mK, 0.3 mS/m, 0.2 dbar) is worth ~0.003 kg/m^3 (1 sigma).
    const double measured = model::seawater::density_from_ctd(cond[i], temp[i], bar_to_dbar(bar[i]));
    worst_rho = std::max(worst_rho, std::abs(measured - rho[i]));
    worst_p = std::max(worst_p, std::abs(bar_to_dbar(bar[i]) - model::sea_pressure_dbar(std::max(depth[i], 0.0))));
  }
  CHECK(sampled > 0.9 * static_cast<double>(log.rows()));
  CHECK(worst_rho < 0.015);  // 5 sigma
  CHECK(worst_p < 0.1);      // 5 sigma of 0.02 dbar
  // Water given by density alone has no salinity: no CTD in the log.
  options.environment = model::still_water(1025.0);
  sil::run_scenario(vehicle, config, options);
  const flightlog::FlightLog plain = flightlog::read_flight_log(options.log_path);
  for (double c : plain.column("sci_water_cond")) CHECK(std::isnan(c));
}

TEST(DemoMission, LogGapsThinTheLogLikeARealSlocumLog) {
  options.environment = model::load_environment_file(GLIDER_SOURCE_DIR "/boards/environments/summer_thermocline.toml");
  options.log_gaps.enabled = true;
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/gaps_a.csv";
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  options.log_path = GLIDER_TEST_OUTPUT_DIR "/gaps_b.csv";
  sil::run_scenario(vehicle, config, options);
  CHECK_TRUE(slurp(GLIDER_TEST_OUTPUT_DIR "/gaps_a.csv") == slurp(GLIDER_TEST_OUTPUT_DIR "/gaps_b.csv"));
  CHECK_TRUE(r.completed);
  CHECK(r.stats.dives().samples > 300);  // the statistics still see every cycle
  const flightlog::FlightLog log = flightlog::read_flight_log(options.log_path);
  LONGS_EQUAL(r.log_rows, log.rows());
  const auto& time = log.time();
  const auto& temp = log.column("sci_water_temp");
  const auto& state = log.column("m_depth_state");
  std::size_t blank = 0, under_water = 0;
  for (std::size_t i = 1; i < log.rows(); ++i) {
    // 1 Hz firmware cycles, a row kept every 2-5 s: 2..5 s apart (the last
    // row, the mission's end, may come sooner).
    CHECK(time[i] - time[i - 1] >= (i + 1 == log.rows() ? 1.0 : 2.0));
    CHECK(time[i] - time[i - 1] <= 5.0);
    if (state[i] != 0.0) {
      ++under_water;
      blank += std::isnan(temp[i]) ? 1 : 0;
    }
  }
  const double blank_fraction = static_cast<double>(blank) / static_cast<double>(under_water);
  CHECK(blank_fraction > 0.02 && blank_fraction < 0.09);  // 5 %, ~1000 rows

  // At the surface (the SIL missions dive at once and end on surfacing, so
  // this is fed directly): no rows for 20-200 s after arriving there.
  model::GliderSimulator sim(vehicle, options.environment);
  const std::string path = GLIDER_TEST_OUTPUT_DIR "/gaps_surface.csv";
  sil::CsvFlightLog csv(path, {}, sim, sil::SimCtd(options.noise, 1), options.log_gaps, 7);
  hal::FlightLogRecord record;
  for (int second = 0; second < 600; ++second) {
    record.time_us = static_cast<hal::Micros>(second) * hal::kMicrosPerSecond;
    record.m_depth_state = second < 250 ? 1 : (second < 500 ? 0 : 1);  // dive, surface, dive
    CHECK_TRUE(csv.write(record));
  }
  CHECK_TRUE(csv.close());
  const flightlog::FlightLog surfaced = flightlog::read_flight_log(path);
  double longest = 0.0, gap_start = 0.0;
  for (std::size_t i = 1; i < surfaced.rows(); ++i) {
    if (surfaced.time()[i] - surfaced.time()[i - 1] > longest) {
      longest = surfaced.time()[i] - surfaced.time()[i - 1];
      gap_start = surfaced.time()[i - 1];
    }
  }
  CHECK(longest >= 20.0 && longest <= 205.0);
  CHECK(gap_start >= 245.0 && gap_start < 250.0);
}

TEST(DemoMission, DepthSensorFailureAbortsAndSurfaces) {
  options.max_sim_time_s = 1200.0;
  double surfaced_at = -1.0;
  options.before_cycle = [&surfaced_at](double t, sil::SimHal& hal) {
    hal.faults().depth_invalid = t >= 300.0;
    (void)surfaced_at;
  };
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  CHECK(r.final_phase == fw::Phase::kAbort);
  CHECK(r.abort_cause == fw::AbortCause::kDepthSensor);
  CHECK_FALSE(r.completed);  // it cannot know it is up without a depth sensor
  // ... but physically it is: full buoyancy, battery aft.
  CHECK(r.final_truth.depth_m < 0.5);
}

TEST(DemoMission, PumpFaultAbortsAndSurfaces) {
  options.before_cycle = [](double t, sil::SimHal& hal) { hal.faults().pump_fault = t >= 500.0; };
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  CHECK(r.abort_cause == fw::AbortCause::kActuatorFault);
  CHECK_TRUE(r.completed);  // surfaced and knows it
  CHECK(r.sim_time_s < 500.0 + 400.0);
}

TEST(DemoMission, LimitsBeyondTheVehicleAreRefused) {
  config.limits.battery_max_in = 1.5;  // the slide only travels 1 in
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  STRCMP_EQUAL("firmware battery limits exceed the vehicle's slide travel", r.error.c_str());
}

TEST(DemoMission, FliesInATidalShelfSeaAndDriftsWithTheWater) {
  const sil::ScenarioResult still = sil::run_scenario(vehicle, config, options);
  options.environment = model::load_environment_file(GLIDER_SOURCE_DIR "/boards/environments/tidal_shelf.toml");
  const sil::ScenarioResult tidal = sil::run_scenario(vehicle, config, options);
  CHECK_TRUE(tidal.completed);
  LONGS_EQUAL(3, tidal.yos);
  // Heading east (90 deg): the water carries the glider by its current
  // integrated along the path, so the extra eastward distance lies between
  // the weakest and the strongest eastward current of the file (0.02 m/s at
  // depth; 0.15 + 0.2 sin(2 pi t / M2) <= 0.19 m/s at the surface over this
  // run) times the time; likewise northward (0 ... 0.05 + 0.1 sin <= 0.07 m/s).
  const double t = tidal.sim_time_s;
  const double extra_east = tidal.final_truth.east_m - still.final_truth.east_m;
  CHECK(extra_east > 0.02 * t && extra_east < 0.19 * t);
  CHECK(tidal.final_truth.north_m > 0.0 && tidal.final_truth.north_m < 0.07 * t);
  DOUBLES_EQUAL(0.0, still.final_truth.north_m, 1e-6);
}
