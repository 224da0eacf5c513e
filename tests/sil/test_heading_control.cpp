// SPDX-License-Identifier: Apache-2.0
// The heading-control study as a regression test (docs/heading-control.md):
// Slocum's autopilot gains on a fin with a 20 s dead time swing like the
// real comet 2016 (+-13 deg, ~100 s); paper 001's P law holds a steady
// error under comet 2019's -10 deg roll; the compensated law removes both.
#include <CppUTest/TestHarness.h>

#include <cmath>
#include <string>

#include "glider/firmware/mission_file/mission_loader.hpp"
#include "glider/flightlog/flight_log.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"
#include "glider/units.hpp"
#include "heading_metrics.hpp"

using namespace glider;

namespace {

heading_study::HeadingMetrics fly(fw::HeadingLaw law, double roll_deg, double delay_s, const std::string& name) {
  model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_comet.toml");
  vehicle.heading.roll_offset_rad = deg_to_rad(roll_deg);
  vehicle.heading.fin_delay_s = delay_s;
  fw::FlightSoftwareConfig base;
  base.heading.law = law;
  base.heading.delay_s = delay_s;
  const auto loaded = fw::mission_file::load_mission_file(GLIDER_SOURCE_DIR "/boards/missions/heading_hold.mi",
                                                          sil::mission_vehicle(vehicle, 102.0), base);
  CHECK_TRUE(loaded.config.has_value());
  sil::ScenarioOptions options;
  options.log_path = std::string(GLIDER_TEST_OUTPUT_DIR) + "/heading_" + name + ".csv";
  const sil::ScenarioResult r = sil::run_scenario(vehicle, *loaded.config, options);
  CHECK_TRUE(r.completed);
  return heading_study::heading_metrics(flightlog::read_flight_log(options.log_path), 900.0);
}

}  // namespace

TEST_GROUP(SilHeading){};

TEST(SilHeading, FinDeadTimeMakesSlocumsGainsSwingAndThePredictorStopsIt) {
  const auto slocum = fly(fw::HeadingLaw::kSlocum, 3.7, 20.0, "slocum_delay20");
  // comet 2016 swings +-13 deg with a ~110 s period (same metric on the real log).
  CHECK_TEXT(slocum.oscillation_amplitude_deg > 10.0, std::to_string(slocum.oscillation_amplitude_deg).c_str());
  CHECK_TEXT(slocum.oscillation_period_s > 70.0 && slocum.oscillation_period_s < 130.0,
             std::to_string(slocum.oscillation_period_s).c_str());
  const auto no_delay = fly(fw::HeadingLaw::kSlocum, 3.7, 0.0, "slocum_delay0");
  CHECK(no_delay.oscillation_amplitude_deg < 3.0);  // without the dead time: no swing
  const auto fixed = fly(fw::HeadingLaw::kCompensated, 3.7, 20.0, "compensated_delay20");
  CHECK(fixed.rms_error_deg < 0.3 * slocum.rms_error_deg);
  CHECK(fixed.oscillation_amplitude_deg < 4.0);
  CHECK(fixed.fin_travel_rad_per_h < slocum.fin_travel_rad_per_h);
}

TEST(SilHeading, RollOffsetHoldsAProportionalErrorTheIntegratorRemoves) {
  const auto p = fly(fw::HeadingLaw::kProportional, -10.0, 0.0, "p_roll10");
  // comet 2019: +17 deg on dives, -12..-18 on climbs (a port-down roll turns a diving Slocum clockwise).
  CHECK(p.dive_error_deg > 8.0);
  CHECK(p.climb_error_deg < -8.0);
  const auto fixed = fly(fw::HeadingLaw::kCompensated, -10.0, 0.0, "compensated_roll10");
  CHECK(std::fabs(fixed.dive_error_deg) < 1.0);
  CHECK(std::fabs(fixed.climb_error_deg) < 1.0);
}
