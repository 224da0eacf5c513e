// SPDX-License-Identifier: Apache-2.0
// The 30-day waypoint mission (~180 surfacings, one call each) with the link
// simulated costs at most twice the CPU time of the same mission without
// comms (the speed bound), and every surfacing is accounted for.
#include <CppUTest/TestHarness.h>

#include <cstdio>
#include <ctime>

#include "glider/firmware/app/mission_setup.hpp"
#include "glider/model/vehicle_file.hpp"
#include "glider/sil/mission_setup.hpp"
#include "glider/sil/scenario.hpp"

using namespace glider;

namespace {

double cpu_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

}  // namespace

TEST_GROUP(CommsMonth){};

TEST(CommsMonth, ThirtyDaysWithTheLinkWithinTwiceWithout) {
  const model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  sil::ScenarioOptions options;
  const fw::app::VehicleSetup setup = sil::vehicle_setup(vehicle, options.fitted, 200.0, false, 1025.0);
  const fw::app::PreparedMission prepared =
      fw::app::prepare_mission(GLIDER_SOURCE_DIR "/boards/missions/month_waypoints/missions/month.mi", setup, {});
  CHECK_TRUE(prepared.config.has_value());
  options.max_sim_time_s = 30.0 * 86400.0;

  double t0 = cpu_s();
  const sil::ScenarioResult without = sil::run_scenario(vehicle, *prepared.config, options);
  const double without_s = cpu_s() - t0;

  sil::FakeShore shore;
  shore.script = {{10.0, "whoru\r"}};
  options.comms.emplace();
  std::snprintf(options.comms->config.vehicle_name, 40, "unit_345");
  std::snprintf(options.comms->config.primary_number, 40, "0088160000519");
  options.comms->far_end = &shore;  // the default link model: 90 % sky, 90 % of calls connect, drops
  t0 = cpu_s();
  const sil::ScenarioResult with = sil::run_scenario(vehicle, *prepared.config, options);
  const double with_s = cpu_s() - t0;

  STRCMP_EQUAL("", without.error.c_str());
  STRCMP_EQUAL("", with.error.c_str());
  std::printf(
      "\n30 days: %.2f s CPU without comms, %.2f s with (x%.2f); %u surfacings, %u calls connected, %u "
      "without a call, %u drops; %llu call cycles, mean %.1f us, max %.1f us\n",
      without_s, with_s, with_s / without_s, with.comms.surfacings, with.comms.calls_connected,
      with.comms.surfacings_without_call, with.comms.carrier_drops, static_cast<unsigned long long>(with.call_cycles),
      with.call_cycle_mean_us, with.call_cycle_max_us);
  CHECK(with.comms.surfacings >= 170);
  CHECK(with.comms.calls_connected + with.comms.surfacings_without_call >= with.comms.surfacings - 1);
  CHECK(with.comms.calls_connected >= with.comms.surfacings * 3 / 4);
  CHECK(with.abort_cause == fw::AbortCause::kNone);
  // Every dialog reached the shore whole (the call is not hung up on text still in the modem).
  std::size_t whole = 0;
  for (std::size_t at = shore.transcript().find("Hit Control-W for a device report\r\n"); at != std::string::npos;
       at = shore.transcript().find("Hit Control-W for a device report\r\n", at + 1)) {
    ++whole;
  }
  LONGS_EQUAL(with.comms.dialogs_printed, whole);
  CHECK_TEXT(with_s <= 2.0 * without_s, "comms more than doubles the month's CPU time");
}
