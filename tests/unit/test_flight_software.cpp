// SPDX-License-Identifier: Apache-2.0
#include <CppUTest/TestHarness.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "fake_hal.hpp"
#include "glider/firmware/flight_software.hpp"
#include "glider/units.hpp"

using namespace glider;
using hal::Micros;

using test::FakeHal;
using test::kNaN;

TEST_GROUP(FlightSoftware) {
  FakeHal fake;
  fw::FlightSoftwareConfig config;

  void cycle(fw::FlightSoftware & flight) {
    flight.run(fake.now);
    fake.now += 1'000'000;
  }
};

TEST(FlightSoftware, StartsTheDiveAndLogsARow) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(0.2, 0.1);
  cycle(flight);
  CHECK(flight.phase() == fw::Phase::kDive);
  DOUBLES_EQUAL(config.mission.dive_ballast_cc, fake.commanded_cc, 0.0);
  DOUBLES_EQUAL(config.dive_battpos_in, fake.commanded_in, 0.0);
  LONGS_EQUAL(1, fake.rows);
  DOUBLES_EQUAL(0.2, fake.last_row.m_depth, 0.0);
  LONGS_EQUAL(1, fake.last_row.m_depth_state);
  CHECK_TRUE(std::isnan(fake.last_row.m_depth_rate));  // needs two samples
}

TEST(FlightSoftware, HoldsTheBatteryUntilThePumpArrives) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(0.2, 0.0);
  cycle(flight);
  // Pump still far from -250 cc, pitch far from target: battery held.
  fake.pump_cc = 0.0;
  fake.sense(0.5, 0.3);
  cycle(flight);
  DOUBLES_EQUAL(config.dive_battpos_in, fake.commanded_in, 0.0);
  // Pump there: the servo acts (nose too high -> battery forward).
  fake.pump_cc = config.mission.dive_ballast_cc;
  fake.sense(1.0, 0.0);
  cycle(flight);
  CHECK(fake.commanded_in > config.dive_battpos_in);
}

TEST(FlightSoftware, CommandsThePumpOnlyWhenTheSetpointChanges) {
  fw::FlightSoftware flight(fake.hal(), config);
  for (int i = 0; i < 5; ++i) {
    fake.sense(1.0 + i, -0.4);
    cycle(flight);
  }
  LONGS_EQUAL(1, fake.pump_commands);
}

TEST(FlightSoftware, StaleDepthAbortsAfterTheTimeoutNotBefore) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(10.0, -0.4);
  cycle(flight);
  const Micros last_good = fake.depth.time_us;
  fake.depth.valid = false;
  while (fake.now - last_good <= static_cast<Micros>(config.sensor_timeout_s * 1e6)) {
    fake.attitude.sample.time_us = fake.now;
    cycle(flight);
    CHECK(flight.phase() == fw::Phase::kDive);
    CHECK_TRUE(std::isnan(fake.last_row.m_depth));  // never a made-up value
  }
  fake.attitude.sample.time_us = fake.now;
  cycle(flight);
  CHECK(flight.phase() == fw::Phase::kAbort);
  CHECK(flight.abort_cause() == fw::AbortCause::kDepthSensor);
  // The abort sequence: full buoyancy, battery full aft.
  DOUBLES_EQUAL(config.limits.ballast_max_cc, fake.commanded_cc, 0.0);
  DOUBLES_EQUAL(config.limits.battery_min_in, fake.commanded_in, 0.0);
  LONGS_EQUAL(static_cast<long>(fw::AbortCause::kDepthSensor), fake.last_row.x_abort_cause);
}

TEST(FlightSoftware, NonFinitePitchIsInvalid) {
  config.sensor_timeout_s = 2.0;
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(5.0, -0.4);
  cycle(flight);
  for (int i = 0; i < 4; ++i) {
    fake.sense(5.0 + i, kNaN);
    cycle(flight);
  }
  CHECK(flight.phase() == fw::Phase::kAbort);
  CHECK(flight.abort_cause() == fw::AbortCause::kAttitudeSensor);
}

// The HAL contract's Euler ranges (attitude_sensor.hpp): a pitch past vertical,
// a roll past 180 deg or a heading outside [0, 360) is no attitude; logged as
// NaN, and held long enough it is the attitude sensor's abort.
TEST(FlightSoftware, AttitudeOutsideTheEulerRangesIsInvalid) {
  config.sensor_timeout_s = 2.0;
  // pitch, roll, heading (rad): each and then the compass's own edges.
  struct Case {
    double pitch, roll, heading;
    bool valid;
  };
  const std::array<Case, 6> cases{{{2.0, 0.0, 1.0, false},
                                   {-204.4, 0.0, 1.0, false},
                                   {-0.4, 3.3, 1.0, false},
                                   {-0.4, 0.0, -0.1, false},
                                   {-0.4, 0.0, 6.3, false},
                                   {deg_to_rad(-90.0), deg_to_rad(180.0), deg_to_rad(359.9), true}}};
  for (const Case& c : cases) {
    FakeHal f;
    fw::FlightSoftware flight(f.hal(), config);
    for (int i = 0; i < 4; ++i) {
      f.sense(5.0 + i, c.pitch);
      f.attitude.sample.roll_rad = c.roll;
      f.attitude.sample.heading_rad = c.heading;
      flight.run(f.now);
      f.now += 1'000'000;
      CHECK_EQUAL(c.valid, !std::isnan(f.last_row.m_pitch));
    }
    CHECK_EQUAL(!c.valid, flight.phase() == fw::Phase::kAbort);
    if (!c.valid) CHECK(flight.abort_cause() == fw::AbortCause::kAttitudeSensor);
  }
}

TEST(FlightSoftware, ActuatorFaultAborts) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.sense(5.0, -0.4);
  cycle(flight);
  fake.pump_fault = true;
  fake.sense(6.0, -0.4);
  cycle(flight);
  CHECK(flight.abort_cause() == fw::AbortCause::kActuatorFault);
  CHECK_TRUE(std::isnan(fake.last_row.m_ballast_pumped));
}

TEST(FlightSoftware, LostLogRowsAreCounted) {
  fw::FlightSoftware flight(fake.hal(), config);
  fake.accept_log = false;
  fake.sense(1.0, 0.0);
  cycle(flight);
  cycle(flight);
  LONGS_EQUAL(2, flight.log_rows_lost());
}

TEST(FlightSoftware, DepthRateIsFilteredFromDepth) {
  fw::FlightSoftware flight(fake.hal(), config);
  for (int i = 0; i < 60; ++i) {  // steady 0.2 m/s descent
    fake.pump_cc = config.mission.dive_ballast_cc;
    fake.sense(1.0 + 0.2 * i, config.mission.dive_pitch_rad);
    cycle(flight);
  }
  DOUBLES_EQUAL(0.2, fake.last_row.m_depth_rate, 1e-9);
}

TEST(FlightSoftware, ValidationNamesTheProblem) {
  STRCMP_EQUAL("", fw::validate(config));
  config.limits.battery_min_in = 2.0;
  STRCMP_EQUAL("battery_min_in must be below battery_max_in", fw::validate(config));
}

TEST(FlightSoftware, SlideMovesSmallerThanTheDeadbandAreNotMade) {
  config.battery_deadband_in = 0.01;
  fw::FlightSoftware flight(fake.hal(), config);
  fake.pump_cc = config.mission.dive_ballast_cc;
  fake.sense(1.0, config.mission.dive_pitch_rad);
  cycle(flight);  // the glide starts at its trim
  const double start = fake.commanded_in;
  // 0.2 deg nose high: kp 1 in/rad moves the servo 0.0035 in, ki adds
  // 0.0007 in/s: the slide stays until the servo has moved 0.01 in.
  int cycles = 0;
  for (; cycles < 60 && fake.commanded_in == start; ++cycles) {
    fake.sense(2.0 + cycles, config.mission.dive_pitch_rad + deg_to_rad(0.2));
    cycle(flight);
  }
  CHECK_TEXT(cycles > 5 && cycles < 60, std::to_string(cycles).c_str());
  CHECK(fake.commanded_in - start >= 0.01);
}

TEST(FlightSoftware, PumpOnlyPitchHoldsTheBatteryWhereTheMissionSays) {
  config.mission.dive_battpos_in = 0.405;
  config.mission.climb_battpos_in = 0.405;
  fw::FlightSoftware flight(fake.hal(), config);
  for (int i = 0; i < 20; ++i) {
    fake.pump_cc = config.mission.dive_ballast_cc;
    fake.sense(1.0 + i, 0.3);  // far from any pitch target: a servo would move
    cycle(flight);
    DOUBLES_EQUAL(0.405, fake.commanded_in, 0.0);
  }
  CHECK_TRUE(std::isnan(fake.last_row.c_pitch));
}
