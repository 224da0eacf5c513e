// SPDX-License-Identifier: Apache-2.0
// The comms state machine over whole surfacings in SIL: the simulated modem
// and link, an in-process shore that records the dialog and types commands.
#include <CppUTest/TestHarness.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <regex>
#include <string>

#include "glider/model/vehicle_file.hpp"
#include "glider/sil/scenario.hpp"

using namespace glider;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A waypoint mission that surfaces every 20 min (when_secs), waits up to
// 120 s for GPS and 300 s for keystrokes, re-prints every 60 s.
fw::FlightSoftwareConfig mission() {
  fw::FlightSoftwareConfig c;
  c.mission.start_at_launch = false;
  c.mission.dive_to_m = 30.0;
  c.mission.climb_to_m = 5.0;
  c.mission.yos = 1000;
  c.mission.max_depth_m = 60.0;
  c.mission.max_duration_s = std::numeric_limits<double>::infinity();
  c.plan.waypoint_count = 1;
  c.plan.waypoints[0] = {41.5, -70.6};  // far away: never reached in the test
  c.plan.legs_to_run = fw::kLegsLoopForever;
  c.plan.surface_interval_s = 1200.0;
  c.plan.gps_wait_s = 120.0;
  c.plan.surface_dwell_s = 300.0;
  c.plan.printout_cycle_s = 60.0;
  return c;
}

sil::ScenarioOptions::Comms comms(sil::FarEnd* shore) {
  sil::ScenarioOptions::Comms c;
  std::snprintf(c.config.vehicle_name, sizeof c.config.vehicle_name, "unit_345");
  std::snprintf(c.config.primary_number, sizeof c.config.primary_number, "0088160000519");
  std::snprintf(c.config.secondary_number, sizeof c.config.secondary_number, "0088160000520");
  const char* sensors[] = {"m_battery", "m_depth", "m_water_vx", "m_water_vy"};
  for (const char* s : sensors) std::snprintf(c.config.sensors[c.config.sensor_count++].data(), 40, "%s", s);
  c.link.drops_per_hour = 0.0;
  c.link.connect_probability = 1.0;
  c.link.availability = 1.0;
  c.far_end = shore;
  return c;
}

}  // namespace

TEST_GROUP(CommsSil) {
  model::VehicleParams vehicle = model::load_vehicle_file(GLIDER_SOURCE_DIR "/boards/vehicles/slocum_we01.toml");
  sil::ScenarioOptions options;
  void setup() override { options.max_sim_time_s = 2000.0; }
};

TEST(CommsSil, FullSurfacingDialogExactLinesAndReprintCadence) {
  sil::FakeShore shore;
  shore.script = {{20.0, "whoru\r"}, {25.0, "!get u_keystroke_wait_time\r"}};
  options.comms = comms(&shore);
  std::vector<double> dialog_times;
  std::size_t seen = 0;
  options.comms->after_cycle = [&](double t, const fw::comms::CommsTask& c) {
    const std::size_t n = c.stats().dialogs_printed;
    if (n > seen) dialog_times.push_back(t);
    seen = n;
  };
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  STRCMP_EQUAL("", r.error.c_str());
  const std::string& t = shore.transcript();
  // The launch call: one connected call, the dialog re-printed every 60 s
  // during the 300 s keystroke wait (the pilot's keys restart the wait).
  CHECK(r.comms.calls_connected >= 1);
  CHECK(dialog_times.size() >= 5);
  for (std::size_t i = 1; i < dialog_times.size() && i < 5; ++i) {
    const double gap = dialog_times[i] - dialog_times[i - 1];
    CHECK_TEXT(std::fabs(gap - 60.0) <= 1.0, ("reprint gap " + std::to_string(gap)).c_str());
  }
  // Every print reached the shore whole.
  LONGS_EQUAL(dialog_times.size(), count(t, "Vehicle Name: unit_345\r\nCurr Time:"));
  // The lines shore tools key on, in their exact formats.
  CHECK(std::regex_search(t, std::regex("\r\nGlider unit_345 at surface\\.\r\n")));
  CHECK(std::regex_search(t, std::regex("Because:[A-Za-z ]+ \\[behavior \\w+ start_when = [0-9.]+\\]\r\n")));
  CHECK(std::regex_search(
      t, std::regex("MissionName:MISSION\\.MI MissionNum:unit_345-\\d{4}-\\d{3}-0-\\d+ \\(\\d{4}\\.\\d{4}\\)\r\n")));
  CHECK(std::regex_search(
      t, std::regex("Curr Time: \\w{3} \\w{3} [ \\d]\\d \\d{2}:\\d{2}:\\d{2} \\d{4} MT:\\s+\\d+\r\n")));
  CHECK(std::regex_search(
      t, std::regex("DR  Location:\\s+-?\\d+\\.\\d{3} N\\s+-?\\d+\\.\\d{3} E measured\\s+[0-9.e+]+ secs ago\r\n")));
  CHECK(std::regex_search(
      t, std::regex("GPS TooFar:   69696969\\.000 N 69696969\\.000 E measured     1e\\+308 secs ago\r\n")));
  CHECK(std::regex_search(
      t, std::regex("GPS Location:\\s+-?\\d+\\.\\d{3} N\\s+-?\\d+\\.\\d{3} E measured\\s+[0-9.]+ secs ago\r\n")));
  CHECK(std::regex_search(t, std::regex("   sensor:m_battery\\(V\\)=[0-9.]+\\s+[0-9.e+]+ secs ago\r\n")));
  CHECK(std::regex_search(t, std::regex("devices:\\(t/m/s\\) errs:\\s*\\d+/\\s*\\d+/\\s*\\d+ "
                                        "warn:\\s*\\d+/\\s*\\d+/\\s*\\d+ odd:\\s*\\d+/\\s*\\d+/\\s*\\d+\r\n")));
  CHECK(std::regex_search(t, std::regex("ABORT HISTORY: total since reset: 0\r\n")));
  CHECK(std::regex_search(t, std::regex("Hit Control-R to RESUME the mission")));
  // The pilot's commands were echoed and answered.
  STRCMP_CONTAINS("whoru\r\nVehicle Name: unit_345\r\n", t.c_str());
  STRCMP_CONTAINS("u_keystroke_wait_time(s)=300", t.c_str());
  // It hung up and dived: the mission goes on.
  CHECK(shore.hangups() >= 1);
  CHECK(r.yos > 0);
  CHECK(r.call_cycles > 0);
  std::printf("\ncomms: %llu call cycles, loop cost during the call: mean %.1f us, max %.1f us\n",
              static_cast<unsigned long long>(r.call_cycles), r.call_cycle_mean_us, r.call_cycle_max_us);
}

TEST(CommsSil, SameSeedSameDialogBytes) {
  options.max_sim_time_s = 1500.0;
  sil::FakeShore a, b;
  a.script = b.script = {{15.0, "whoru\r"}};
  options.comms = comms(&a);
  options.comms->link.availability = 0.7;
  options.comms->link.corruption = 0.001;
  options.comms->link.drops_per_hour = 2.0;
  options.comms->link.connect_probability = 0.8;
  sil::run_scenario(vehicle, mission(), options);
  options.comms->far_end = &b;
  sil::run_scenario(vehicle, mission(), options);
  CHECK(a.transcript().size() > 1000);
  CHECK(a.transcript() == b.transcript());
}

TEST(CommsSil, LinkDownForThreeSurfacingsKeepsTheMissionAndItsNoCommsLimit) {
  options.max_sim_time_s = 4.5 * 3600.0;
  sil::FakeShore shore;
  options.comms = comms(&shore);
  options.comms->link.outage_from_s = 0.0;
  options.comms->link.outage_to_s = 1e9;  // no satellite all flight
  std::vector<double> dives;
  bool was_under = false;
  double longest_without_attempt_s = 0.0;
  double last_surface_s = 0.0;
  options.comms->after_cycle = [&](double t, const fw::comms::CommsTask& c) {
    const bool under = c.state() == fw::comms::CommsState::kIdle;
    if (under && !was_under) dives.push_back(t);
    if (!under) last_surface_s = t;
    longest_without_attempt_s = std::max(longest_without_attempt_s, t - last_surface_s);
    was_under = under;
  };
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  STRCMP_EQUAL("", r.error.c_str());
  CHECK(r.comms.surfacings >= 3);
  LONGS_EQUAL(0, r.comms.calls_connected);
  // Every surfacing gave up calling (the last may still be trying when the run stops).
  CHECK(r.comms.surfacings_without_call + 1 >= r.comms.surfacings);
  CHECK(r.comms.dial_attempts == 0);  // CSQ 0 all along: it never dialled into no sky
  LONGS_EQUAL(0, shore.calls());
  CHECK(r.abort_cause == fw::AbortCause::kNone);
  CHECK(dives.size() >= 3);  // it dived again after every failed surfacing
  // "No comms for" when_secs (1200 s): the surfacing is asked for by then;
  // add the climb from 30 m (at >= 0.15 m/s: 200 s) to the antenna.
  std::printf("\nlink down: %u surfacings, longest under water between tries %.0f s\n", r.comms.surfacings,
              longest_without_attempt_s);
  CHECK_TEXT(longest_without_attempt_s <= 1200.0 + 200.0, std::to_string(longest_without_attempt_s).c_str());
}

namespace {

// Arrivals at the surface (the comms task leaves idle), call starts and the
// when_secs clock's firings (the navigator asks for the surface by start_when 9), in simulated seconds.
struct SurfacingTimes {
  std::vector<double> arrivals, connects, dives, firings;
};

SurfacingTimes fly_and_time(const model::VehicleParams& vehicle, const fw::FlightSoftwareConfig& config,
                            sil::ScenarioOptions& options) {
  SurfacingTimes times;
  bool was_idle = true;
  std::uint32_t calls = 0;
  options.comms->after_cycle = [&](double t, const fw::comms::CommsTask& c) {
    const bool idle = c.state() == fw::comms::CommsState::kIdle;
    if (was_idle && !idle) times.arrivals.push_back(t);
    if (!was_idle && idle) times.dives.push_back(t);
    if (c.stats().calls_connected > calls) times.connects.push_back(t);
    calls = c.stats().calls_connected;
    was_idle = idle;
  };
  int fired_before = 0;
  options.stop_when = [&](double t, const fw::FlightSoftware& flight, const model::Truth&) {
    const int fired = flight.navigator().surfaced_by_start_when();
    if (fired == 9 && fired_before != 9) times.firings.push_back(t);
    fired_before = fired;
    return false;
  };
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  STRCMP_EQUAL("", r.error.c_str());
  return times;
}

}  // namespace

// Slocum's surface behaviour, start_when 9 (every when_secs): periodic, the
// clock runs from its own previous firing (the time at the surface and the
// climb after the firing included; from launch the first time). Real comet-2019
// (when_secs 10800): x_surface_active went to 4 10809 s apart (a 4.5 s log
// cycle) at 17.6 m and 4.0 m, the arrivals at 1 m 10700 s apart - counted
// from the arrival they would be at least 10800 s plus a climb (and from the
// dive, this firmware's first clock, 18 min late). Here: 1200 s, about 400 s
// at the surface (300 s keystroke wait).
TEST(CommsSil, EveryWhenSecsCountsFromItsPreviousFiring) {
  options.max_sim_time_s = 4000.0;
  sil::FakeShore shore;
  shore.script = {{15.0, "whoru\r"}};
  options.comms = comms(&shore);
  const SurfacingTimes t = fly_and_time(vehicle, mission(), options);
  std::printf("\n%zu arrivals, %zu firings", t.arrivals.size(), t.firings.size());
  CHECK(t.arrivals.size() >= 3 && t.firings.size() >= t.arrivals.size() - 1);
  // The first from launch (simulated time 0).
  CHECK_TEXT(std::fabs(t.firings[0] - 1200.0) <= 1.0, std::to_string(t.firings[0]).c_str());
  for (std::size_t i = 1; i < t.arrivals.size(); ++i) {
    const double period = t.arrivals[i] - t.arrivals[i - 1];
    const double at_surface = t.dives[i - 1] - t.arrivals[i - 1];
    const double climb = t.arrivals[i] - t.firings[i - 1];
    std::printf("\nsurfacing %zu: %.0f s after the previous one, which stayed up %.0f s; fired %.0f s before", i,
                period, at_surface, climb);
    CHECK_TEXT(at_surface >= 300.0, "the test's premise: the time at the surface is long");
    // The climb from where it fired (<= 30 m at >= 0.15 m/s: 200 s).
    CHECK_TEXT(climb >= 0.0 && climb <= 200.0, std::to_string(climb).c_str());
    if (i < t.firings.size()) {
      // when_secs from the previous firing (one control cycle either way);
      // counted from the arrival it would be when_secs + that climb.
      const double fired = t.firings[i] - t.firings[i - 1];
      CHECK_TEXT(std::fabs(fired - 1200.0) <= 1.0, std::to_string(fired).c_str());
    }
  }
}

// A flight resumed mid-mission (the forecast starts at the dive) carries the
// clocks over: the when_secs clock started and the call connected 500 s
// before this start, so when_secs 1200 fires ~700 s after launch, the later
// firings every 1200 s.
TEST(CommsSil, SeededClocksCountFromBeforeTheStart) {
  options.max_sim_time_s = 3000.0;
  sil::FakeShore shore;
  shore.script = {{15.0, "whoru\r"}};
  options.comms = comms(&shore);
  options.before_launch = [](fw::FlightSoftware& flight) { flight.seed_clocks(500.0, 500.0); };
  const SurfacingTimes t = fly_and_time(vehicle, mission(), options);
  CHECK(t.arrivals.size() >= 3 && t.firings.size() >= 2);
  std::printf("\nseeded 500 s: fired at %.1f and %.1f s, surfacings at %.0f and %.0f s", t.firings[0], t.firings[1],
              t.arrivals[1], t.arrivals[2]);
  CHECK_TEXT(std::fabs(t.firings[0] - 700.0) <= 1.0, std::to_string(t.firings[0]).c_str());
  CHECK_TEXT(t.arrivals[1] - t.firings[0] >= 0.0 && t.arrivals[1] - t.firings[0] <= 200.0,
             std::to_string(t.arrivals[1] - t.firings[0]).c_str());
  const double period = t.firings[1] - t.firings[0];
  CHECK_TEXT(std::fabs(period - 1200.0) <= 1.0, std::to_string(period).c_str());
}

// start_when 12 (no comms for when_secs): the clock runs from the last call
// connected. With the link up that is each surfacing's call; with the link
// down after the first call, the vehicle keeps coming up (it has had no
// comms for when_secs) rather than diving on for another when_secs.
TEST(CommsSil, NoCommsForWhenSecsCountsFromTheLastCall) {
  options.max_sim_time_s = 4000.0;
  fw::FlightSoftwareConfig config = mission();
  config.plan.surface_interval_s = 0.0;
  config.plan.no_comms_interval_s = 1200.0;
  sil::FakeShore shore;
  shore.script = {{15.0, "whoru\r"}};
  options.comms = comms(&shore);
  const SurfacingTimes up = fly_and_time(vehicle, config, options);
  CHECK(up.arrivals.size() >= 3 && up.connects.size() >= up.arrivals.size() - 1);
  for (std::size_t i = 1; i < up.arrivals.size() && i - 1 < up.connects.size(); ++i) {
    const double since_call = up.arrivals[i] - up.connects[i - 1];
    std::printf("\nlink up: surfacing %zu %.0f s after the previous call connected", i, since_call);
    CHECK_TEXT(since_call >= 1200.0 && since_call <= 1200.0 + 200.0, std::to_string(since_call).c_str());
  }

  sil::ScenarioOptions down_options;
  down_options.max_sim_time_s = 4000.0;
  sil::FakeShore down_shore;
  down_options.comms = comms(&down_shore);
  down_options.comms->link.outage_from_s = 900.0;  // the launch call connects, none after it
  down_options.comms->link.outage_to_s = 1e9;
  const SurfacingTimes down = fly_and_time(vehicle, config, down_options);
  LONGS_EQUAL(1, down.connects.size());
  CHECK(down.arrivals.size() >= 3);
  CHECK_TEXT(down.arrivals[1] - down.connects[0] >= 1200.0 && down.arrivals[1] - down.connects[0] <= 1400.0,
             std::to_string(down.arrivals[1] - down.connects[0]).c_str());
  for (std::size_t i = 2; i < down.arrivals.size(); ++i) {
    const double under = down.arrivals[i] - down.dives[i - 1];
    std::printf("\nlink down: surfacing %zu after %.0f s under water", i, under);
    CHECK_TEXT(under <= 200.0, std::to_string(under).c_str());  // back up at once: still no comms
  }
}

TEST(CommsSil, PrimaryDeadThenSecondaryNumber) {
  options.max_sim_time_s = 900.0;
  sil::FakeShore shore;
  shore.dead_numbers = {"0088160000519"};
  options.comms = comms(&shore);
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  // Two tries on the primary (no answer), then the secondary answers.
  CHECK(shore.numbers().size() >= 3);
  STRCMP_EQUAL("0088160000519", shore.numbers()[0].c_str());
  STRCMP_EQUAL("0088160000519", shore.numbers()[1].c_str());
  STRCMP_EQUAL("0088160000520", shore.numbers()[2].c_str());
  LONGS_EQUAL(1, shore.calls());
  CHECK(r.comms.calls_connected >= 1);
}

// Dropped 100 s into the launch call for 30 s; `dcd`: whether the line has
// the carrier-detect wire (without it the modem's NO CARRIER tells).
void carrier_drop_redials(const model::VehicleParams& vehicle, sil::ScenarioOptions options, bool dcd) {
  options.max_sim_time_s = 900.0;
  sil::FakeShore shore;
  options.comms = comms(&shore);
  options.comms->link.dcd_wired = dcd;
  // The sky goes away 60 s into the launch call for 30 s.
  std::optional<double> first_connect;
  options.comms->after_cycle = [&](double t, const fw::comms::CommsTask& c) {
    if (!first_connect && c.state() == fw::comms::CommsState::kDialog) first_connect = t;
  };
  options.comms->link.outage_from_s = 100.0;
  options.comms->link.outage_to_s = 130.0;
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  CHECK(first_connect.has_value());
  CHECK(*first_connect < 100.0);
  LONGS_EQUAL(1, r.modem.drops);
  LONGS_EQUAL(1, r.comms.carrier_drops);
  CHECK(r.comms.calls_connected >= 2);  // called again after the drop
  CHECK(shore.calls() >= 2);
}

TEST(CommsSil, CarrierDropMidDialogRedials) { carrier_drop_redials(vehicle, options, true); }

TEST(CommsSil, CarrierDropWithoutDcdSeenByNoCarrier) { carrier_drop_redials(vehicle, options, false); }

TEST(CommsSil, ControlCEndsTheMissionAndRunFliesItOn) {
  options.max_sim_time_s = 1500.0;
  sil::FakeShore shore;
  shore.script = {{20.0, "\x03"}, {30.0, "!put u_keystroke_wait_time 5\r"}, {40.0, "run\r"}};
  options.comms = comms(&shore);
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  const std::string& t = shore.transcript();
  STRCMP_CONTAINS("^C\r\nMission ended by the operator.", t.c_str());
  STRCMP_CONTAINS("u_keystroke_wait_time(s)=5", t.c_str());
  STRCMP_CONTAINS("run\r\nMission restarted", t.c_str());
  CHECK(r.yos > 0);  // it dived after run
}

TEST(CommsSil, CorruptedLinkNeverCrashesTheConsole) {
  options.max_sim_time_s = 900.0;
  sil::FakeShore shore;
  std::string noise;
  for (int i = 0; i < 3000; ++i) {
    const char c = static_cast<char>((i * 197 + 13) % 256);
    if (c != 0x03 && c != 0x06 && c != 0x12 && c != 0x17) noise.push_back(c);  // no command keys
  }
  shore.script = {{10.0, noise}, {40.0, "\rwhoru\r"}};
  options.comms = comms(&shore);
  options.comms->link.corruption = 0.05;
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  STRCMP_EQUAL("", r.error.c_str());
  CHECK(r.modem.corrupted > 0);
  CHECK(r.comms.calls_connected >= 1);
  // (A corrupted byte can become a command key: Control-C would end the
  // mission, as on a real console; so the test does not ask for a dive.)
}

TEST(CommsSil, NoKeystrokeWaitStillDeliversTheWholeDialog) {
  // end_action 2 (resume): no keystroke wait; the call ends only once the
  // text has had time to leave the modem at the link's rate.
  options.max_sim_time_s = 900.0;
  sil::FakeShore shore;
  options.comms = comms(&shore);
  options.comms->link.bytes_per_s = 100.0;  // a slow link: the dialog needs ~10 s to leave the modem
  options.comms->config.link_bytes_per_s = 100.0;
  fw::FlightSoftwareConfig config = mission();
  config.plan.surface_dwell_s = 0.0;
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  CHECK(r.comms.calls_connected >= 1);
  LONGS_EQUAL(r.comms.dialogs_printed, count(shore.transcript(), "Hit Control-W for a device report\r\n"));
  CHECK(r.yos > 0);
}

TEST(CommsSil, ShoreNotListeningKeepsTheMission) {
  options.max_sim_time_s = 3.0 * 3600.0;
  sil::FakeShore shore;
  shore.listening = false;  // every call: NO CARRIER
  options.comms = comms(&shore);
  const sil::ScenarioResult r = sil::run_scenario(vehicle, mission(), options);
  STRCMP_EQUAL("", r.error.c_str());
  CHECK(r.comms.surfacings >= 3);
  LONGS_EQUAL(0, r.comms.calls_connected);
  // Both numbers tried twice at every finished surfacing, then it gave up and dived.
  CHECK(r.comms.dial_attempts >= 4 * (r.comms.surfacings - 1));
  CHECK(r.comms.surfacings_without_call + 1 >= r.comms.surfacings);
  CHECK(r.abort_cause == fw::AbortCause::kNone);
  CHECK(r.yos > 0);
}

TEST(CommsSil, CallbackHangsUpAndCallsAgainLater) {
  options.max_sim_time_s = 1200.0;
  sil::FakeShore shore;
  shore.script = {{20.0, "callback 2\r"}};
  options.comms = comms(&shore);
  std::vector<double> connects;
  fw::comms::CommsState last = fw::comms::CommsState::kIdle;
  options.comms->after_cycle = [&](double t, const fw::comms::CommsTask& c) {
    if (c.state() == fw::comms::CommsState::kDialog && last != fw::comms::CommsState::kDialog) connects.push_back(t);
    last = c.state();
  };
  sil::run_scenario(vehicle, mission(), options);
  STRCMP_CONTAINS("Hanging up: calling back in 2 minutes", shore.transcript().c_str());
  CHECK(connects.size() >= 2);
  // Two minutes after the hang-up, plus the call set-up (12-20 s).
  CHECK(connects[1] - connects[0] >= 120.0 + 20.0);
  CHECK(connects[1] - connects[0] <= 120.0 + 80.0);
}

namespace {

// A file-transfer engine stand-in: moves its files' bytes over the call's
// stream a slice per cycle (as the Zmodem engine will), then reports done.
struct SliceTransfer final : fw::comms::FileTransfer {
  std::vector<std::string> files{"unit_345-2026-100-0-0.sbd", "unit_345-2026-100-0-1.sbd"};
  std::size_t to_send = 0, sent = 0;
  int polls = 0, files_asked = 0;
  std::size_t file_count() const override { return files.size(); }
  const char* file_name(std::size_t i) const override { return files[i].c_str(); }
  bool begin_send(std::span<const fw::comms::FileName> names) override {
    files_asked = static_cast<int>(names.size());
    to_send = 600 * names.size();
    sent = 0;
    return true;
  }
  bool begin_receive() override { return false; }
  fw::comms::TransferProgress poll(hal::Micros, fw::comms::ByteStream& stream) override {
    ++polls;
    std::array<std::uint8_t, 128> slice{};
    slice.fill('Z');
    const std::size_t n = std::min(slice.size(), to_send - sent);
    sent += stream.write(std::span<const std::uint8_t>(slice.data(), n));
    if (sent < to_send) return {fw::comms::TransferState::kRunning, 0, 0, sent};
    return {fw::comms::TransferState::kDone, files_asked, 0, sent};
  }
  void cancel() override {}
};

}  // namespace

TEST(CommsSil, SendHandsTheFilesToTheTransferEngine) {
  options.max_sim_time_s = 900.0;
  sil::FakeShore shore;
  shore.script = {{30.0, "s *.sbd\r"}};
  SliceTransfer transfer;
  options.comms = comms(&shore);
  options.comms->transfer = &transfer;
  sil::run_scenario(vehicle, mission(), options);
  LONGS_EQUAL(2, transfer.files_asked);
  CHECK(transfer.polls >= 10);  // 1200 bytes, 128 a cycle
  const std::string& t = shore.transcript();
  STRCMP_CONTAINS("Sending 2 file(s)", t.c_str());
  STRCMP_CONTAINS("transfer complete: 2 file(s) done, 0 failed, 1200 bytes", t.c_str());
  LONGS_EQUAL(1200, count(t, "Z"));  // the engine's bytes, not mixed with dialog text
}

TEST(CommsSil, MissionOverMakesOneLastCallThenTheRunEnds) {
  // One waypoint where the vehicle is launched: the mission is over at the
  // first fix (the navigator decides once the call lets it go). The vehicle
  // calls once, hangs up, and the run ends there instead of calling on.
  options.max_sim_time_s = 6.0 * 3600.0;
  sil::FakeShore shore;
  options.comms = comms(&shore);
  fw::FlightSoftwareConfig config = mission();
  config.plan.waypoints[0] = options.peripherals.gps.launch;
  config.plan.legs_to_run = 1;
  const sil::ScenarioResult r = sil::run_scenario(vehicle, config, options);
  CHECK_TRUE(r.completed);
  LONGS_EQUAL(1, r.comms.calls_connected);
  STRCMP_CONTAINS("Because:Stack idle [behavior surface start_when = 1.0]", shore.transcript().c_str());
  CHECK(r.sim_time_s < 1800.0);
  LONGS_EQUAL(1, shore.hangups());
}

namespace {

// A log writer that lags behind the loop (the target's writer thread): rows
// are written `lag_s` after their cycle, or never.
struct LaggingWriter final : fw::comms::LogProgress {
  double lag_s = 0.0;
  bool stuck = false;
  double now_s = 0.0;
  bool written_through(hal::Micros time_us) override { return !stuck && now_s - hal::to_seconds(time_us) >= lag_s; }
};

// Seconds from the first cycle at the surface (the comms task out of idle)
// to the modem's start (the call begins), in the launch call.
double surfacing_to_dial_s(const model::VehicleParams& vehicle, sil::ScenarioOptions options, LaggingWriter* writer) {
  sil::FakeShore shore;
  options.max_sim_time_s = 300.0;
  options.peripherals.gps.time_to_first_fix_min_s = 2.0;  // a fix at once: the log is what the call waits for
  options.peripherals.gps.time_to_first_fix_max_s = 3.0;
  options.comms = comms(&shore);
  options.comms->log_progress = writer;
  double up_s = -1.0, dial_s = -1.0;
  options.comms->after_cycle = [&](double t, const fw::comms::CommsTask& c) {
    if (writer != nullptr) writer->now_s = t + 1.0;  // the next cycle's "now"
    if (up_s < 0.0 && c.state() != fw::comms::CommsState::kIdle) up_s = t;
    if (dial_s < 0.0 && c.state() == fw::comms::CommsState::kModemStart) dial_s = t;
  };
  sil::run_scenario(vehicle, mission(), options);
  return up_s >= 0.0 && dial_s >= 0.0 ? dial_s - up_s : -1.0;
}

}  // namespace

TEST(CommsSil, CallWaitsForTheLogWriterToCloseTheSegment) {
  // The segment closed at a surfacing must be a whole file when the call's
  // first `send` lists the folder: a call waits for the rows up to its
  // surfacing to be written (the target writes them on a thread, up to
  // 500 ms later; at time scale 100 that is 50 simulated seconds).
  const double in_cycle = surfacing_to_dial_s(vehicle, options, nullptr);
  LaggingWriter lagging;
  lagging.lag_s = 20.0;
  const double behind = surfacing_to_dial_s(vehicle, options, &lagging);
  LaggingWriter stuck;
  stuck.stuck = true;
  const double never = surfacing_to_dial_s(vehicle, options, &stuck);
  // In cycle: the call starts at the first fix.
  CHECK_TEXT(in_cycle >= 0.0 && in_cycle <= 15.0, std::to_string(in_cycle).c_str());
  // Written 20 s late: the call waits for it (the surfacing's row, then the next cycle).
  CHECK_TEXT(behind >= 20.0 && behind <= 23.0, std::to_string(behind).c_str());
  // A writer that never catches up delays the call by the bound (30 s), no more.
  CHECK_TEXT(never >= 30.0 && never <= 33.0, std::to_string(never).c_str());
}
